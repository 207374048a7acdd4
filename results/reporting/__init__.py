"""The generated sections of results/README.md (results/report.py writes them)."""
