#include "cavity/core/io/point_io.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/io/atomic_file.h"
#include "file_extension.h"
#include "point_readers.h"
#include "point_writers.h"
#include "text_input.h"
#include "text_output.h"

namespace cavity::core {

void write_node(AtomicFileGroup::Writer& out, const PointSet& points) {
    // A .node input's attributes and markers are written back as read (the weight among them,
    // as attribute 0); points from elsewhere carry the weight as their only attribute.
    const bool own_attributes = points.attribute_count > 0;
    const std::size_t attribute_count = own_attributes      ? points.attribute_count
                                        : points.weighted() ? 1
                                                            : 0;
    const bool markers = !points.markers.empty();
    std::string text;
    append_uint(text, points.size());
    text += " 3 ";
    append_uint(text, attribute_count);
    text += markers ? " 1\n" : " 0\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        append_uint(text, i + static_cast<std::size_t>(points.index_base));
        for (const double c : {points.points[i].x, points.points[i].y, points.points[i].z}) {
            text += ' ';
            append_double(text, c);
        }
        if (own_attributes) {
            for (std::size_t a = 0; a < attribute_count; ++a) {
                text += ' ';
                append_double(text, points.attributes[i * attribute_count + a]);
            }
        } else if (points.weighted()) {
            text += ' ';
            append_double(text, points.weights[i]);
        }
        if (markers) {
            text += ' ';
            append_int(text, points.markers[i]);
        }
        text += '\n';
        out.write(text);
        text.clear();
    }
}

void write_xyz(AtomicFileGroup::Writer& out, const PointSet& points, char separator) {
    std::string text;
    for (std::size_t i = 0; i < points.size(); ++i) {
        append_double(text, points.points[i].x);
        text += separator;
        append_double(text, points.points[i].y);
        text += separator;
        append_double(text, points.points[i].z);
        if (points.weighted()) {
            text += separator;
            append_double(text, points.weights[i]);
        }
        text += '\n';
        out.write(text);
        text.clear();
    }
}

PointSet read_points(const std::filesystem::path& file, bool weighted) {
    const std::string extension = lower_extension(file);
    const std::string name = file.string();
    std::error_code error;
    if (std::filesystem::is_directory(file, error)) {
        throw Error(located_message(name, std::nullopt, "is a directory, not a point file"));
    }
    if (extension != ".node" && extension != ".xyz" && extension != ".csv" && extension != ".txt" &&
        extension != ".ply") {
        throw Error(located_message(
            name,
            std::nullopt,
            "unknown point format '" + extension + "' (expected .node, .xyz, .csv, .txt or .ply)"));
    }
    const std::string bytes = read_file_bytes(file);
    if (extension == ".node") {
        return read_node(name, bytes, weighted);
    }
    if (extension == ".ply") {
        return read_ply(name, bytes, weighted);
    }
    return read_xyz(name, bytes, weighted);
}

void write_points(const std::filesystem::path& file, const PointSet& points) {
    const std::string extension = lower_extension(file);
    AtomicFileGroup group;
    if (extension == ".node") {
        write_node(group.add(file), points);
    } else if (extension == ".xyz" || extension == ".txt") {
        write_xyz(group.add(file), points, ' ');
    } else if (extension == ".csv") {
        write_xyz(group.add(file), points, ',');
    } else {
        throw Error(located_message(
            file.string(),
            std::nullopt,
            "cannot write points as '" + extension + "' (expected .node, .xyz, .txt or .csv)"));
    }
    group.commit();
}

}  // namespace cavity::core
