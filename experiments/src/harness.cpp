#include "cavity/experiments/harness.h"

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cavity/core/base/error.h"
#include "cavity/core/io/atomic_file.h"
#include "cavity/experiments/metadata.h"
#include "cavity/experiments/run.h"

namespace cavity::experiments {

namespace {

namespace fs = std::filesystem;
using core::Error;

std::string join(const std::vector<std::string>& fields) {
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        line += (i ? "," : "") + fields[i];
    }
    return line;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) {
        fields.push_back(field);
    }
    if (!line.empty() && line.back() == ',') {
        fields.emplace_back();
    }
    return fields;
}

/// A table file: its header and its complete rows (a last line without its newline, the trace
/// of an interrupted write, is dropped).
struct Table {
    std::string header;
    std::vector<std::string> rows;
};

Table read_table(const fs::path& path, std::size_t columns) {
    Table table;
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t start = 0;
    bool first = true;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string::npos) {
            break;
        }
        std::string line = text.substr(start, end - start);
        start = end + 1;
        if (first) {
            table.header = line;
            first = false;
        } else if (split(line).size() == columns) {
            table.rows.push_back(line);
        }
    }
    return table;
}

std::string key_of_row(const std::string& row) {
    const std::vector<std::string> fields = split(row);
    const std::size_t k = key_columns().size();
    return join(std::vector<std::string>(fields.begin(), fields.begin() + static_cast<long>(k)));
}

struct Paths {
    fs::path csv, j_csv, meta, part, j_part;
};

Paths paths_for(const fs::path& dir,
                const std::string& name,
                std::uint64_t index,
                std::uint64_t count) {
    const std::string part =
        name + ".part-" + std::to_string(index) + "-of-" + std::to_string(count);
    return {dir / (name + ".csv"),
            dir / (name + ".j.csv"),
            dir / (name + ".meta.json"),
            dir / (part + ".csv"),
            dir / (part + ".j.csv")};
}

/// Appends whole lines and flushes, so a crash leaves complete rows behind.
void append_lines(const fs::path& path, const std::vector<std::string>& lines) {
    std::ofstream out(path, std::ios::binary | std::ios::app);
    for (const std::string& line : lines) {
        out << line << '\n';
    }
    out.flush();
    if (!out) {
        throw Error(path.string() + ": cannot append to the file");
    }
}

/// Prepares a part file with `header`: kept when resuming and its header matches, else started
/// afresh. Returns the keys of the rows already complete.
std::set<std::string> open_part(const fs::path& path,
                                const std::string& header,
                                std::size_t columns,
                                bool resume) {
    std::set<std::string> done;
    if (resume && fs::exists(path)) {
        const Table table = read_table(path, columns);
        if (table.header != header) {
            throw Error(path.string() +
                        ": its header differs from the suite's columns; run without --resume");
        }
        // Rewrite without a torn last line, so later appends start on a fresh line.
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << header << '\n';
        for (const std::string& row : table.rows) {
            out << row << '\n';
            done.insert(key_of_row(row));
        }
        return done;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << header << '\n';
    if (!out) {
        throw Error(path.string() + ": cannot create the file");
    }
    return done;
}

/// Seeds a missing part file from a merged table made earlier, so --resume after a completed
/// run (or with a different shard count) redoes nothing already measured.
void seed_part_from_merged(const fs::path& merged,
                           const fs::path& part,
                           const std::string& header,
                           std::size_t columns,
                           const std::set<std::string>& shard_keys) {
    if (fs::exists(part) || !fs::exists(merged)) {
        return;
    }
    const Table table = read_table(merged, columns);
    if (table.header != header) {
        return;
    }
    std::vector<std::string> lines{header};
    for (const std::string& row : table.rows) {
        if (shard_keys.count(key_of_row(row)) != 0) {
            lines.push_back(row);
        }
    }
    append_lines(part, lines);
}

}  // namespace

HarnessResult run_experiment(const HarnessOptions& options) {
    Suite suite = read_suite(options.suite_file);
    TierSettings settings = suite.tier(options.tier);
    if (options.seed) {
        settings.seeds = {*options.seed};
    }
    if (options.shard_count == 0 || options.shard_index == 0 ||
        options.shard_index > options.shard_count) {
        throw Error("shard " + std::to_string(options.shard_index) + "/" +
                    std::to_string(options.shard_count) + ": must be i/N with 1 <= i <= N");
    }
    fs::create_directories(options.out_dir);
    const std::vector<RunSpec> runs = enumerate_runs(suite, settings);
    std::vector<std::string> columns = key_columns();
    for (const std::string& c : metric_columns(suite.kind)) {
        columns.push_back(c);
    }
    std::vector<std::string> j_cols = key_columns();
    const std::vector<std::string> j_metrics = j_columns(suite.kind);
    for (const std::string& c : j_metrics) {
        j_cols.push_back(c);
    }
    const bool has_j = !j_metrics.empty();
    const std::string header = join(columns);
    const std::string j_header = join(j_cols);
    const Paths mine =
        paths_for(options.out_dir, suite.name, options.shard_index, options.shard_count);

    HarnessResult result;
    result.runs_total = runs.size();
    result.csv = mine.part;
    if (!options.merge_only) {
        std::set<std::string> shard_keys;
        std::vector<std::size_t> shard_runs;
        for (std::size_t k = 0; k < runs.size(); ++k) {
            if (k % options.shard_count == options.shard_index - 1) {
                shard_runs.push_back(k);
                shard_keys.insert(join(key_values(runs[k])));
            }
        }
        if (options.resume) {
            seed_part_from_merged(mine.csv, mine.part, header, columns.size(), shard_keys);
            if (has_j) {
                seed_part_from_merged(mine.j_csv, mine.j_part, j_header, j_cols.size(), shard_keys);
            }
        }
        const std::set<std::string> done =
            open_part(mine.part, header, columns.size(), options.resume);
        if (has_j) {
            open_part(mine.j_part, j_header, j_cols.size(), options.resume);
        }
        double total_cost = 0;
        for (std::size_t k : shard_runs) {
            total_cost += run_cost(suite, settings, runs[k]);
        }
        double done_cost = 0;
        for (std::size_t k : shard_runs) {
            const RunSpec& run = runs[k];
            const std::string key = join(key_values(run));
            const double cost = run_cost(suite, settings, run);
            if (done.count(key) != 0) {
                ++result.runs_skipped;
                done_cost += cost;
                continue;
            }
            RunOutput output;
            try {
                output = execute_run(suite, settings, run);
            } catch (const Error& e) {
                throw Error(suite.file + ": run " + key + ": " + e.what());
            }
            if (has_j) {
                std::vector<std::string> lines;
                for (const auto& row : output.j_rows) {
                    lines.push_back(key + "," + join(row));
                }
                append_lines(mine.j_part, lines);
            }
            append_lines(mine.part, {key + "," + join(output.values)});
            ++result.runs_done;
            done_cost += cost;
            if (options.progress) {
                options.progress(done_cost, total_cost);
            }
        }
    }

    // Merge when every part is present and complete.
    std::map<std::string, std::string> rows;
    std::map<std::string, std::vector<std::string>> j_rows;
    std::size_t missing_parts = 0;
    for (std::uint64_t i = 1; i <= options.shard_count; ++i) {
        const Paths part = paths_for(options.out_dir, suite.name, i, options.shard_count);
        if (!fs::exists(part.part)) {
            ++missing_parts;
            continue;
        }
        for (const std::string& row : read_table(part.part, columns.size()).rows) {
            rows[key_of_row(row)] = row;
        }
        if (has_j) {
            for (const std::string& row : read_table(part.j_part, j_cols.size()).rows) {
                const std::string key = key_of_row(row);
                auto& list = j_rows[key];
                // A run interrupted after its j rows and redone appends them twice: keep the
                // last complete set, which starts again at the run's first j.
                if (!list.empty() &&
                    split(row)[key_columns().size()] == split(list.front())[key_columns().size()]) {
                    list.clear();
                }
                list.push_back(row);
            }
        }
    }
    std::size_t missing_rows = 0;
    for (const RunSpec& run : runs) {
        missing_rows += rows.count(join(key_values(run))) == 0 ? 1 : 0;
    }
    if (options.partial && rows.empty()) {
        throw Error(suite.name + ": nothing to merge: no run of this tier is measured in " +
                    options.out_dir.string() + " by " + std::to_string(options.shard_count) +
                    " shard(s) (--shard i/N gives the count N the parts were run with)");
    }
    if ((missing_parts != 0 || missing_rows != 0) && !(options.merge_only && options.partial)) {
        if (options.merge_only) {
            throw Error(suite.name + ": cannot merge: " + std::to_string(missing_parts) +
                        " part file(s) and " + std::to_string(missing_rows) + " run(s) missing");
        }
        return result;
    }
    core::AtomicFileGroup group;
    std::string table = header + "\n";
    std::string j_table = j_header + "\n";
    for (const RunSpec& run : runs) {
        const std::string key = join(key_values(run));
        const auto row = rows.find(key);
        if (row == rows.end()) {
            continue;  // a partial merge: the run is not measured yet
        }
        table += row->second + "\n";
        for (const std::string& j_row : j_rows[key]) {
            j_table += j_row + "\n";
        }
    }
    group.add(mine.csv).write(table);
    if (has_j) {
        group.add(mine.j_csv).write(j_table);
    }
    group.add(mine.meta).write(metadata_json(suite,
                                             options.tier,
                                             settings,
                                             runs.size(),
                                             runs.size() - missing_rows,
                                             options.shard_count,
                                             options.command_line));
    group.commit();
    for (std::uint64_t i = 1; i <= options.shard_count; ++i) {
        const Paths part = paths_for(options.out_dir, suite.name, i, options.shard_count);
        fs::remove(part.part);
        fs::remove(part.j_part);
    }
    result.merged = true;
    result.csv = mine.csv;
    return result;
}

}  // namespace cavity::experiments
