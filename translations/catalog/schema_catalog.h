#pragma once
// The texts of the dialects' records that people read (settings labels, groups, units, option
// names, help; actions and presets), written out as a C++ file for lupdate: the schemas are
// Qt-free data, so their texts are marked for translation here, one context per dialect
// ("Schema/nvs"), and translated where they are shown (ui/settings/schema_texts.h).
#include <span>
#include <string>
#include <vector>

namespace gnss {
struct Dialect;
class DialectRegistry;
namespace sim {
class SimulatorTable;
}

// The whole catalog file, deterministic: the same dialects give the same bytes.
std::string schemaCatalogSource(std::span<const Dialect *const> dialects,
                                const DialectRegistry &registry,
                                const sim::SimulatorTable &simulators);

// Every text of one dialect the catalog lists, in first-seen order, without repeats.
std::vector<std::string> schemaTexts(const Dialect &d);

// The titles and field names of the status reports a dialect's receiver gives (the Receiver
// dock shows them): found by asking the dialect's simulated receiver everything it answers
// in `simulators` (the identity probe and every setting's query) and decoding the replies into the
// receiver state, as the application does. A title's trailing number ("... (PNMRX603) 2") is
// dropped.
std::vector<std::string> reportTexts(const Dialect &d, const DialectRegistry &registry,
                                     const sim::SimulatorTable &simulators);
// "Reports": the translation context of report titles and field names, shared by the dialects.
inline constexpr const char *kReportsContext = "Reports";

} // namespace gnss
