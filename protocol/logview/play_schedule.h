#pragma once
// When each epoch of a log is played out: seconds from the first epoch, by the recording's host
// times when it has them, else the epochs' own times; a time that goes back (a reset) or is
// missing adds nothing. Shared by `gnss-cli play` and the window's Play Out.
#include "logview/epoch_record.h"

#include <span>
#include <vector>

namespace gnss::logview {

// Seconds after the first epoch at which each record is due, at `speed` (> 0) times the log's pace.
std::vector<double> playSchedule(std::span<const EpochRecord> records, bool hostTimes,
                                 double speed = 1);

} // namespace gnss::logview
