#pragma once
// ReceiverState: everything the views show, vendor-neutral. The epoch (time, fix, position, sky)
// comes from the standard sentences; RTK status, attitude, time marks, identity and status
// reports come from each dialect's `updateState` hook, which translates its own messages here.
// Views read this (through Qt models) and never see a vendor sentence.
#include "core/field_types.h"
#include "state/epoch.h"

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>

namespace gnss {

struct BaselineState {
    std::optional<double> north, east, vertical, length; // metres
    std::optional<double> course, pitch;                 // degrees
    std::optional<char> mode;                            // mode letter of the sentence
    bool present() const { return length.has_value() || north.has_value(); }
    bool operator==(const BaselineState &) const = default;
};

struct RtkState {
    bool seen = false;        // the receiver reports RTK information at all
    std::optional<char> mode; // R fixed, F float, A autonomous, D differential, ...
    std::optional<std::int64_t> rtcmTotal, rtcmErrors, rtcmOk;
    std::optional<double> baseDistance;  // metres
    std::optional<double> correctionAge; // seconds
    std::optional<int> baseStationId;
    BaselineState baseToRover;                            // base-to-rover vector
    BaselineState antennas;                               // dual-antenna baseline (heading)
    std::optional<double> heading;                        // degrees true
    std::optional<double> sdLat, sdLon, sdHeight;         // metres
    std::optional<double> sdVelNorth, sdVelEast, sdVelUp; // m/s
    std::optional<double> sdHeading;                      // degrees
    std::optional<double> gdop, pdop, hdop, vdop, tdop, ndop, edop;
    std::optional<double> velNorth, velEast, velUp; // m/s
    bool operator==(const RtkState &) const = default;
};

struct AttitudeState {
    bool seen = false;
    std::optional<TimeOfDay> time;
    std::optional<double> roll, pitch, yaw;           // degrees
    std::optional<double> accNorth, accEast, accDown; // m/s^2
    bool operator==(const AttitudeState &) const = default;
};

struct TimeMarkEvent {
    std::optional<std::int64_t> counter;
    std::optional<double> towSeconds; // GPS time of week
    std::optional<TimeOfDay> utc;
    std::optional<double> lat, lon, altMsl;
    bool operator==(const TimeMarkEvent &) const = default;
};

struct ReceiverIdentity {
    std::string vendor, model, firmware, hardware;
    bool operator==(const ReceiverIdentity &) const = default;
};

struct ReceiverState {
    Epoch epoch;
    RtkState rtk;
    AttitudeState attitude;
    std::deque<TimeMarkEvent> timeMarks; // newest last, bounded (kMaxTimeMarks)
    ReceiverIdentity identity;
    // Status reports as the receiver gave them, by title ("Self-test", "Status word"): the JSON
    // of the latest message, shown as a tree of named flags.
    std::map<std::string, std::string> reports;
    std::optional<bool> jamming; // jamming detected (where the receiver says)

    static constexpr std::size_t kMaxTimeMarks = 1000;
    // Equal states give equal views (and, in a StateTracker, equal futures: see sameFuture).
    bool operator==(const ReceiverState &) const = default;
    void addTimeMark(const TimeMarkEvent &e) {
        timeMarks.push_back(e);
        while (timeMarks.size() > kMaxTimeMarks) timeMarks.pop_front();
    }
};

} // namespace gnss
