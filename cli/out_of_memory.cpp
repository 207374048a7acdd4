#include "out_of_memory.h"

#include <cstdio>

namespace cavity::cli {

std::string about_bytes(double bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
    int unit = 0;
    while (bytes >= 1024 && unit < 5) {
        bytes /= 1024;
        ++unit;
    }
    char text[64];
    std::snprintf(text, sizeof text, "about %.1f %s", bytes, units[unit]);
    return text;
}

}  // namespace cavity::cli
