#include "core/fix_type.h"

namespace gnss {

std::string_view toString(FixType f) {
    switch (f) {
    case FixType::None: return "none";
    case FixType::Estimated: return "estimated";
    case FixType::Fix2D: return "2d";
    case FixType::Fix3D: return "3d";
    case FixType::Dgnss: return "dgnss";
    case FixType::RtkFloat: return "rtk_float";
    case FixType::RtkFixed: return "rtk_fixed";
    case FixType::Manual: return "manual";
    case FixType::Simulator: return "simulator";
    }
    return "none";
}

FixType fixTypeFromGgaQuality(int q) {
    switch (q) {
    case 0: return FixType::None;
    case 1: return FixType::Fix3D;
    case 2: return FixType::Dgnss;
    case 3: return FixType::Fix3D; // PPS fix
    case 4: return FixType::RtkFixed;
    case 5: return FixType::RtkFloat;
    case 6: return FixType::Estimated;
    case 7: return FixType::Manual;
    case 8: return FixType::Simulator;
    default: return FixType::Fix3D;
    }
}

FixType fixTypeFromModeIndicator(char m) {
    switch (m) {
    case 'A': return FixType::Fix3D;
    case 'D': return FixType::Dgnss;
    case 'P': return FixType::Dgnss; // precise
    case 'E': return FixType::Estimated;
    case 'F': return FixType::RtkFloat;
    case 'R': return FixType::RtkFixed;
    case 'M': return FixType::Manual;
    case 'S': return FixType::Simulator;
    default: return FixType::None; // N, V, unknown
    }
}

} // namespace gnss
