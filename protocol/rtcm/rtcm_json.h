#pragma once
// JSON of RTCM messages, as `gnss-cli rtcm` prints them: one object per message,
// {"type":1005,"length":19,"station":2003,...decoded fields...}, "error" when not decoded.
#include "core/json_writer.h"
#include "rtcm/rtcm_messages.h"

namespace gnss::rtcm {

class RtcmStreamDecoder;

void writeRtcmJson(JsonWriter &w, const RtcmMessage &m);

// The stream's counts: frames, bytes, bytes skipped, CRC failures, reserved bits set, truncated
// frames, decode errors and frames per message type ({"1005":1,"1077":60}).
void writeRtcmSummaryJson(JsonWriter &w, const RtcmStreamDecoder &d);

} // namespace gnss::rtcm
