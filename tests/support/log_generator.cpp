#include "log_generator.h"

#include "core/sentence_builder.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

namespace gnss::bench {
namespace {

struct Sys {
    const char *talker;
    int systemId;
    int count;
    int firstId;
    int signalId;
};

constexpr Sys kSystems[] = {
        {"GP", 1, 12, 1, 1}, {"GL", 2, 8, 65, 1}, {"GA", 3, 8, 1, 7}, {"GB", 4, 10, 1, 1}};

void add(std::string &out, const char *body) {
    out += buildSentence(body);
    out += "\r\n";
}

} // namespace

void generateLog(std::string &out, std::size_t bytes) {
    LogGenerator().append(out, bytes);
}

void LogGenerator::append(std::string &out, std::size_t bytes) {
    char b[256];
    long &epoch = epoch_;
    while (out.size() < bytes) {
        const long tenths = epoch % 864000;
        const int h = static_cast<int>(tenths / 36000), m = static_cast<int>(tenths / 600 % 60);
        const double s = static_cast<double>(tenths % 600) / 10.0;
        const double lat = 4807.0380 + 0.0001 * std::sin(epoch * 0.01);
        const double lon = 1131.0000 + 0.0001 * std::cos(epoch * 0.01);
        std::snprintf(b, sizeof b,
                      "GNRMC,%02d%02d%04.1f0,A,%.6f,N,%011.6f,E,0.012,087.3,230394,,,R,V", h, m, s,
                      lat, lon);
        add(out, b);
        std::snprintf(b, sizeof b,
                      "GNGGA,%02d%02d%04.1f0,%.6f,N,%011.6f,E,4,28,0.6,545.421,M,46.912,M,1.0,0031",
                      h, m, s, lat, lon);
        add(out, b);
        for (const Sys &sys : kSystems) {
            std::string gsa = std::string("GNGSA,A,3");
            for (int i = 0; i < 12; ++i) {
                if (i < sys.count - 2) {
                    std::snprintf(b, sizeof b, ",%02d", sys.firstId + i);
                    gsa += b;
                } else {
                    gsa += ",";
                }
            }
            std::snprintf(b, sizeof b, ",1.1,0.6,0.9,%d", sys.systemId);
            gsa += b;
            add(out, gsa.c_str());
        }
        for (const Sys &sys : kSystems) {
            const int parts = (sys.count + 3) / 4;
            for (int p = 0; p < parts; ++p) {
                std::string gsv;
                std::snprintf(b, sizeof b, "%sGSV,%d,%d,%02d", sys.talker, parts, p + 1, sys.count);
                gsv = b;
                for (int k = p * 4; k < std::min(sys.count, p * 4 + 4); ++k) {
                    const int el = 5 + (k * 7 + static_cast<int>(epoch / 600)) % 85;
                    const int az = (k * 37 + static_cast<int>(epoch / 100)) % 360;
                    std::snprintf(b, sizeof b, ",%02d,%02d,%03d,%02d", sys.firstId + k, el, az,
                                  30 + el / 5);
                    gsv += b;
                }
                std::snprintf(b, sizeof b, ",%d", sys.signalId);
                gsv += b;
                add(out, gsv.c_str());
            }
        }
        add(out, "GNVTG,087.3,T,,M,0.012,N,0.022,K,R");
        std::snprintf(b, sizeof b, "GNZDA,%02d%02d%04.1f0,23,03,1994,00,00", h, m, s);
        add(out, b);
        std::snprintf(b, sizeof b,
                      "GNGST,%02d%02d%04.1f0,0.006,0.023,0.020,273.6,0.023,0.020,0.031", h, m, s);
        add(out, b);
        ++epoch;
    }
}

bool writeLogFile(const std::string &path, std::size_t bytes) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::string log;
        log.reserve(bytes + 4096);
        generateLog(log, bytes);
        std::FILE *f = std::fopen(path.c_str(), "wb");
        const bool ok = f && std::fwrite(log.data(), 1, log.size(), f) == log.size();
        if (f) std::fclose(f);
        std::_Exit(ok ? 0 : 1);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

long statusKb(const char *key) {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + std::strlen(key));
    return -1;
}

} // namespace gnss::bench
