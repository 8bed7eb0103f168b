#include "Core/Memory.h"

#include <atomic>
#include <cstdio>
#include <fstream>

#include <unistd.h>

namespace fabguide {

namespace {

/// The memory free when the run starts (MemAvailable: free, and caches the system gives back), else the
/// machine's.
double freeMemory()
{
    std::ifstream info("/proc/meminfo");
    std::string key;
    double kilobytes = 0;
    while (info >> key >> kilobytes)
        if (key == "MemAvailable:" && kilobytes > 0)
            return kilobytes * 1024;
        else
            info.ignore(1 << 10, '\n');
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? static_cast<double>(pages) * size : 8e9;
}

std::atomic<double>& limit()
{
    static std::atomic<double> bytes{freeMemory()};
    return bytes;
}

}  // namespace

double memoryLimit()
{
    return limit();
}

void setMemoryLimit(double bytes)
{
    limit() = bytes;
}

void needMemory(double bytes, const std::string& what, const std::string& remedy)
{
    if (bytes > memoryLimit())
        throw MemoryError(what + " ~" + inBytes(bytes) + ", more than the " + inBytes(memoryLimit()) +
                          " of memory the run may use (the memory free when it began, or --memory)" + remedy);
}

std::string inBytes(double bytes)
{
    char text[32];
    if (bytes >= 9.95e9)
        std::snprintf(text, sizeof text, "%.0f GB", bytes / 1e9);
    else if (bytes >= 1e9)
        std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    else
        std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
    return text;
}

}  // namespace fabguide
