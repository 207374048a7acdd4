#include "cavity/core/mesh/facet_gluer.h"

namespace cavity::core {

namespace {

std::uint64_t edge_key(VertexId p, VertexId q) {
    return (static_cast<std::uint64_t>(p) << 32) | q;
}

}  // namespace

std::size_t FacetGluer::slot(std::uint64_t edge) const {
    std::uint64_t h = edge * 0x9E37'79B9'7F4A'7C15ull;
    h ^= h >> 29;
    return static_cast<std::size_t>(h) & (table_.size() - 1);
}

void FacetGluer::grow() {
    std::vector<Entry> old(2 * table_.size(), Entry{kEmpty, kNoHalfFacet});
    old.swap(table_);
    table_touched_.clear();
    for (const Entry& e : old) {
        if (e.edge != kEmpty) {
            std::size_t i = slot(e.edge);
            while (table_[i].edge != kEmpty) {
                i = (i + 1) & (table_.size() - 1);
            }
            table_[i] = e;
            table_touched_.push_back(i);
        }
    }
}

HalfFacet FacetGluer::match_hashed(VertexId p, VertexId q, HalfFacet h) {
    const std::uint64_t partner = edge_key(q, p);
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = slot(partner); table_[i].edge != kEmpty; i = (i + 1) & mask) {
        if (table_[i].edge == partner && table_[i].value != kNoHalfFacet) {
            const HalfFacet found = table_[i].value;
            table_[i].value = kNoHalfFacet;  // matched: a face has exactly two sides
            return found;
        }
    }
    if (2 * (table_touched_.size() + 1) > table_.size()) {
        grow();
    }
    const std::uint64_t own = edge_key(p, q);
    std::size_t j = slot(own);
    while (table_[j].edge != kEmpty) {
        j = (j + 1) & (table_.size() - 1);
    }
    table_[j] = Entry{own, h};
    table_touched_.push_back(j);
    return kNoHalfFacet;
}

void FacetGluer::end() {
    for (std::size_t i : table_touched_) {
        table_[i] = Entry{kEmpty, kNoHalfFacet};
    }
    table_touched_.clear();
}

}  // namespace cavity::core
