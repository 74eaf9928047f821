#pragma once
// A generated log with known events, for the log viewer's tests: fix changes (no fix → 3D →
// RTK float → RTK fixed), a data gap, a receiver reset (time back), a checksum-error burst,
// binary junk, NVS time marks, GeoStar jamming on and off (RQUERY status word), base station
// changes, optionally no date (time of day only) across midnight. Every sentence is built with
// buildSentence (right checksums) unless it is meant to be wrong.
#include "core/sentence_builder.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gnss::test {

struct Scenario {
    int epochs = 600;                    // epochs written (gap epochs are not)
    bool withDate = true;                // RMC carries the date
    int startSeconds = 36000;            // 10:00:00
    int gapFrom = 300, gapLength = 30;   // epochs [gapFrom, gapFrom + gapLength) are missing
    int resetAt = 400, resetBack = 3600; // at epoch resetAt the time goes back by resetBack s
    int badFrom = 350, badCount = 3;     // epochs with a wrong-checksum GSV
    std::vector<int> timeMarks{150, 450};
    int jammingOn = 250, jammingOff = 260;
    int junkAt = 500;
    bool vendor = true; // time marks and jamming (NVS and GeoStar sentences)
};

struct ScenarioTruth {
    int epochs = 0;
    int fixChanges = 0;
    int gaps = 1;
    int timeJumps = 1;
    int checksumErrors = 0;
};

inline const char *scenarioQuality(const Scenario &sc, int e) {
    if (e >= sc.resetAt && e < sc.resetAt + 5) return "0";
    if (e >= sc.resetAt + 5) return "1";
    if (e < 10) return "0";
    if (e < 100) return "1";
    if (e < 200) return "5";
    return "4";
}

inline std::string scenarioLog(const Scenario &sc, ScenarioTruth *truth = nullptr) {
    std::string out;
    auto add = [&](const std::string &body) { out += buildSentence(body) + "\r\n"; };
    char b[512];
    ScenarioTruth t;
    std::string prevQ;
    for (int e = 0; e < sc.epochs + sc.gapLength; ++e) {
        if (e >= sc.gapFrom && e < sc.gapFrom + sc.gapLength) continue;
        int sec = sc.startSeconds + e;
        if (e >= sc.resetAt) sec -= sc.resetBack;
        const int day = sec / 86400;
        sec %= 86400;
        const int h = sec / 3600, m = sec / 60 % 60, s = sec % 60;
        const std::string q = scenarioQuality(sc, e);
        const bool fix = q != "0";
        const double lat = 5550.602948 + 0.00001 * std::sin(e * 0.7);
        const double lon = 3732.239612 + 0.00001 * std::cos(e * 0.3);
        char date[16];
        std::snprintf(date, sizeof date, "%02d0324", 15 + day);
        std::string pos = fix ? std::string() : ",,,";
        if (fix) {
            std::snprintf(b, sizeof b, "%.6f,N,%011.6f,E", lat, lon);
            pos = b;
        }
        std::snprintf(b, sizeof b, "GPRMC,%02d%02d%02d.00,%s,%s,0.05,0.0,%s,,,%s", h, m, s,
                      fix ? "A" : "V", pos.c_str(), sc.withDate ? date : "",
                      q == "4"   ? "R"
                      : q == "5" ? "F"
                      : fix      ? "A"
                                 : "N");
        add(b);
        const int station = e >= 420 ? 12 : e >= 200 ? 31 : -1;
        std::snprintf(b, sizeof b, "GPGGA,%02d%02d%02d.00,%s,%s,%d,0.8,120.5,M,14.4,M,%s,%s", h, m,
                      s, pos.c_str(), q.c_str(), fix ? 9 : 0, station >= 0 ? "1.0" : "",
                      station >= 0 ? std::to_string(station).c_str() : "");
        add(b);
        add(fix ? "GPGSA,A,3,01,02,03,04,05,06,07,08,09,,,,1.6,0.8,1.4"
                : "GPGSA,A,1,,,,,,,,,,,,,,,");
        add("GPGSV,2,1,06,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45");
        if (e >= sc.badFrom && e < sc.badFrom + sc.badCount) {
            out += "$GPGSV,2,2,06,05,10,010,30,06,55,120,42*00\r\n"; // wrong checksum
            ++t.checksumErrors;
        } else {
            add("GPGSV,2,2,06,05,10,010,30,06,55,120,42");
        }
        if (sc.vendor) {
            for (int mark : sc.timeMarks)
                if (e == mark) {
                    std::snprintf(b, sizeof b, "PNVGTME,%d,%d.125", e, 100000 + e);
                    add(b);
                }
            if (e == sc.jammingOn)
                add("GPSGG,RQUERY,GEOS-5,V.5.102,100518,80083037,802DC097,F7FF8064");
            if (e == sc.jammingOff)
                add("GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064");
        }
        if (e == sc.junkAt)
            out += std::string("\xD3\x00\x05\x01\x02\x03\x04\x05\x06\x07\x00\x00", 12);
        if (!prevQ.empty() && q != prevQ) ++t.fixChanges;
        prevQ = q;
        ++t.epochs;
    }
    if (truth) *truth = t;
    return out;
}

} // namespace gnss::test
