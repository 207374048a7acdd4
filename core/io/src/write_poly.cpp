#include "cavity/core/io/write_poly.h"

#include <string>

#include "text_output.h"

namespace cavity::core {

namespace {

void append_point(std::string& text, const Point3& p) {
    append_double(text, p.x);
    text += ' ';
    append_double(text, p.y);
    text += ' ';
    append_double(text, p.z);
    text += '\n';
}

}  // namespace

void write_poly(AtomicFileGroup::Writer& out, const Plc& plc) {
    const auto base = static_cast<std::uint64_t>(plc.points.index_base);
    std::string text = "# the PLC a cavity mesh conforms to\n";
    append_uint(text, plc.points.size());
    text += " 3 0 0\n";
    for (std::size_t i = 0; i < plc.points.size(); ++i) {
        append_uint(text, i + base);
        text += ' ';
        append_point(text, plc.points.points[i]);
        out.write(text);
        text.clear();
    }
    append_uint(text, plc.facets.size() + plc.segments.size());
    text += " 1\n";
    for (const PlcFacet& facet : plc.facets) {
        append_uint(text, facet.loops.size());
        text += ' ';
        append_uint(text, facet.holes.size());
        text += ' ' + std::to_string(facet.marker) + '\n';
        for (const auto& loop : facet.loops) {
            append_uint(text, loop.size());
            for (std::uint32_t c : loop) {
                text += ' ';
                append_uint(text, c + base);
            }
            text += '\n';
        }
        for (std::size_t h = 0; h < facet.holes.size(); ++h) {
            append_uint(text, h + base);
            text += ' ';
            append_point(text, facet.holes[h]);
        }
        out.write(text);
        text.clear();
    }
    for (const auto& s : plc.segments) {
        text += "1 0 0\n2 ";
        append_uint(text, s[0] + base);
        text += ' ';
        append_uint(text, s[1] + base);
        text += '\n';
        out.write(text);
        text.clear();
    }
    append_uint(text, plc.volume_holes.size());
    text += '\n';
    for (std::size_t h = 0; h < plc.volume_holes.size(); ++h) {
        append_uint(text, h + base);
        text += ' ';
        append_point(text, plc.volume_holes[h].point);
    }
    if (!plc.regions.empty()) {
        append_uint(text, plc.regions.size());
        text += '\n';
        for (std::size_t r = 0; r < plc.regions.size(); ++r) {
            append_uint(text, r + base);
            text += ' ';
            append_point(text, plc.regions[r].point);
            text.pop_back();  // the marker follows on the same line
            text += ' ' + std::to_string(plc.regions[r].marker) + '\n';
        }
    }
    out.write(text);
}

}  // namespace cavity::core
