# Storage, Bowyer–Watson insertion, point location, validation.
