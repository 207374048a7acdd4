#include "cavity/experiments/suite.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cavity/core/base/error.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/plc_families.h"
#include "format.h"
#include "suite_kinds.h"

namespace cavity::experiments {

namespace {

using core::Error;
using core::located_message;

std::vector<std::string> split_words(std::string_view line) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
            ++i;
        }
        if (i > start) {
            words.emplace_back(line.substr(start, i - start));
        }
    }
    return words;
}

/// Reads one line's values, turning every problem into an Error located at that line.
class LineReader {
public:
    LineReader(const std::string& file, std::size_t line) : file_(file), line_(line) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(located_message(file_, line_, what));
    }

    std::uint64_t integer(const std::string& word) const {
        std::uint64_t value = 0;
        const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (ec != std::errc{} || end != word.data() + word.size()) {
            fail("'" + word + "' is not a non-negative integer");
        }
        return value;
    }

    /// Integers, where `A..B` stands for A, A+1, ..., B.
    std::vector<std::uint64_t> integers(const std::vector<std::string>& words) const {
        std::vector<std::uint64_t> values;
        for (const std::string& word : words) {
            const std::size_t dots = word.find("..");
            if (dots == std::string::npos) {
                values.push_back(integer(word));
                continue;
            }
            const std::uint64_t first = integer(word.substr(0, dots));
            const std::uint64_t last = integer(word.substr(dots + 2));
            if (last < first || last - first > 100000) {
                fail("bad range '" + word + "'");
            }
            for (std::uint64_t v = first; v <= last; ++v) {
                values.push_back(v);
            }
        }
        return values;
    }

    template <class Check>
    std::vector<std::string> names(const std::vector<std::string>& words, Check check) const {
        for (const std::string& word : words) {
            try {
                check(word);
            } catch (const Error& e) {
                fail(e.what());
            }
        }
        return words;
    }

private:
    const std::string& file_;
    std::size_t line_;
};

SuiteKind parse_kind(const LineReader& reader, const std::string& word) {
    std::string names;
    for (const SuiteKindInfo& info : suite_kinds()) {
        if (word == info.name) {
            return info.kind;
        }
        names += (names.empty() ? "" : ", ") + std::string(info.name);
    }
    reader.fail("unknown kind '" + word + "' (" + names + ")");
}

void check_distribution(const std::string& name) {
    for (const core::Distribution& d : core::distributions()) {
        if (d.name == name) {
            return;
        }
    }
    throw Error("unknown distribution '" + name + "'");
}

void check_plc_family(const std::string& name) {
    for (const PlcFamily& f : plc_families()) {
        if (f.name == name) {
            return;
        }
    }
    throw Error("unknown PLC family '" + name + "'");
}

void check_order(const std::string& name) {
    if (name != "greedy") {                   // Exercise 1's adversary (triangulation runs)
        detail::order_options(name, 0.5, 0);  // throws Error for an unknown name or a bad ratio
    }
}

/// The tier a per-tier key such as `n.paper` sets, or null when `key` is not `prefix` + a tier.
TierSettings* tier_of_key(Suite& suite, const std::string& key, std::string_view prefix) {
    if (key.rfind(prefix, 0) != 0) {
        return nullptr;
    }
    const std::string_view tier = std::string_view(key).substr(prefix.size());
    if (tier == "quick") {
        return &suite.quick;
    }
    if (tier == "full") {
        return &suite.full;
    }
    return tier == "paper" ? &suite.paper : nullptr;
}

}  // namespace

std::string_view suite_kind_name(SuiteKind kind) {
    return suite_kind_info(kind).name;
}

const TierSettings& Suite::tier(std::string_view tier_name) const {
    if (tier_name == "quick") {
        return quick;
    }
    if (tier_name == "full") {
        return full;
    }
    if (tier_name == "paper") {
        if (paper.sizes.empty()) {
            throw Error(file + ": the suite has no paper tier (no n.paper key)");
        }
        return paper;
    }
    throw Error("unknown tier '" + std::string(tier_name) + "' (quick, full or paper)");
}

Suite parse_suite(std::string_view text, const std::string& file, const std::string& name) {
    Suite suite;
    suite.name = name;
    suite.file = file;
    std::set<std::string> seen;
    bool validate_given = false;
    // Distribution names are checked once the kind is known: cdt suites name PLC families.
    std::size_t dist_line = 0;
    std::map<std::string, std::size_t> cap_lines;
    std::size_t line_number = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        ++line_number;
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
            line = line.substr(0, hash);
        }
        std::vector<std::string> words = split_words(line);
        if (words.empty()) {
            continue;
        }
        const LineReader reader(file, line_number);
        // `cap` may appear once per distribution: its identity is the key and the name.
        const std::string key = words.front();
        words.erase(words.begin());
        const std::string identity =
            key == "cap" && !words.empty() ? key + " " + words.front() : key;
        if (!seen.insert(identity).second) {
            reader.fail("key '" + identity + "' given twice");
        }
        if (words.empty()) {
            reader.fail("key '" + key + "' has no value");
        }
        const auto single = [&]() -> const std::string& {
            if (words.size() != 1) {
                reader.fail("key '" + key + "' takes one value");
            }
            return words.front();
        };
        if (key == "question") {
            std::string joined;
            for (const std::string& w : words) {
                joined += (joined.empty() ? "" : " ") + w;
            }
            suite.question = joined;
        } else if (key == "kind") {
            suite.kind = parse_kind(reader, single());
        } else if (key == "dist") {
            suite.distributions = words;
            dist_line = line_number;
        } else if (key == "order") {
            suite.orders = reader.names(words, check_order);
        } else if (key == "locate") {
            suite.locators = reader.names(words, core::parse_locate_kind);
        } else if (key == "storage") {
            suite.storages = reader.names(words, core::parse_storage_kind);
        } else if (key == "count-conflicts") {
            const std::string& w = single();
            if (w != "yes" && w != "no") {
                reader.fail("count-conflicts takes yes or no, not '" + w + "'");
            }
            suite.count_conflicts = w == "yes";
        } else if (key == "brio-ratio") {
            const std::string& w = single();
            char* stop = nullptr;
            suite.brio_ratio = std::strtod(w.c_str(), &stop);
            if (stop != w.c_str() + w.size() || !(suite.brio_ratio >= 0 && suite.brio_ratio < 1)) {
                reader.fail("brio-ratio must be a number in [0, 1), not '" + w + "'");
            }
        } else if (TierSettings* sizes_of = tier_of_key(suite, key, "n.")) {
            sizes_of->sizes = reader.integers(words);
        } else if (TierSettings* seeds_of = tier_of_key(suite, key, "seeds.")) {
            seeds_of->seeds = reader.integers(words);
        } else if (TierSettings* orders_of = tier_of_key(suite, key, "orders.")) {
            orders_of->orders = reader.integer(single());
            if (orders_of->orders == 0) {
                reader.fail("orders must be positive");
            }
        } else if (TierSettings* added_of = tier_of_key(suite, key, "added.")) {
            added_of->added = reader.integers(words);
        } else if (TierSettings* deletions_of = tier_of_key(suite, key, "deletions.")) {
            deletions_of->deletions = reader.integer(single());
        } else if (key == "prefix") {
            suite.prefix = reader.integer(single());
            if (suite.prefix < 4) {
                reader.fail("prefix must be at least 4 (the bootstrap tetrahedron)");
            }
        } else if (key == "bootstrap") {
            const std::string& w = single();
            if (w != "widest" && w != "first") {
                reader.fail("bootstrap takes widest or first, not '" + w + "'");
            }
            suite.bootstrap_first = w == "first";
        } else if (key == "validate") {
            const std::string& w = single();
            if (w != "yes" && w != "no" && w.find_first_not_of("0123456789") != std::string::npos) {
                reader.fail("validate takes yes, no or a number of points, not '" + w + "'");
            }
            suite.validate = w != "no";
            if (w != "yes" && w != "no") {
                suite.validate_max = reader.integer(w);
            }
            validate_given = true;
        } else if (key == "cap") {
            if (words.size() != 2) {
                reader.fail("cap takes a distribution and a size");
            }
            suite.caps[words[0]] = reader.integer(words[1]);
            cap_lines[words[0]] = line_number;
        } else {
            reader.fail("unknown key '" + key + "'");
        }
    }
    for (const char* required :
         {"question", "kind", "dist", "n.quick", "n.full", "seeds.quick", "seeds.full"}) {
        if (seen.count(required) == 0) {
            throw Error(
                located_message(file, std::nullopt, std::string("missing key '") + required + "'"));
        }
    }
    const auto check_name = suite.kind == SuiteKind::kCdt ? check_plc_family : check_distribution;
    LineReader(file, dist_line).names(suite.distributions, check_name);
    for (const auto& [capped, line] : cap_lines) {
        LineReader(file, line).names({capped}, check_name);
    }
    if (seen.count("n.paper") != seen.count("seeds.paper")) {
        throw Error(located_message(file, std::nullopt, "n.paper and seeds.paper go together"));
    }
    for (const TierSettings* t : {&suite.quick, &suite.full, &suite.paper}) {
        if (std::find(t->sizes.begin(), t->sizes.end(), 0u) != t->sizes.end()) {
            throw Error(located_message(file, std::nullopt, "a size of 0 points"));
        }
    }
    if (suite.kind == SuiteKind::kExtend &&
        (suite.quick.added.empty() || suite.full.added.empty() ||
         (!suite.paper.sizes.empty() && suite.paper.added.empty()))) {
        throw Error(
            located_message(file, std::nullopt, "an extend suite needs added.TIER for every tier"));
    }
    if (suite.prefix != 0 && (suite.kind != SuiteKind::kRuns || !suite.count_conflicts)) {
        // A prefix measures the early conflicts of a run; without them it measures nothing.
        throw Error(
            located_message(file, std::nullopt, "prefix needs kind runs and count-conflicts yes"));
    }
    if (!validate_given) {
        suite.validate = suite.kind == SuiteKind::kDegenerate || suite.kind == SuiteKind::kCdt;
    }
    return suite;
}

Suite read_suite(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw Error(located_message(path.string(), std::nullopt, "cannot open the suite file"));
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_suite(text.str(), path.string(), path.stem().string());
}

}  // namespace cavity::experiments
