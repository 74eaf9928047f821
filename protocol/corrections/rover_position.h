#pragma once
// The rover's fix as the GGA an NTRIP caster is sent (network mountpoints compute the corrections
// for it): from the receiver's epoch, with GGA's quality numbers. None without a position.
#include "ntrip/gga_upload.h"
#include "state/epoch.h"

#include <optional>

namespace gnss::corrections {

std::optional<ntrip::GgaPosition> ggaPositionOf(const Epoch &epoch);

} // namespace gnss::corrections
