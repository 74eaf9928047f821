#pragma once
// Reads ../shared/specs/examples.tsv: every example sentence printed in the three specs, with the
// printed and computed checksums and a verdict (ok, typo + corrected text, bad, placeholder).
#include <string>
#include <vector>

namespace gnss::test {

struct SpecExample {
    std::string vendor;  // nvs, geostar, nemerix
    std::string printed; // as printed in the spec
    std::string docChecksum, computedChecksum;
    std::string verdict;   // ok, typo, bad, placeholder
    std::string corrected; // for typos: the sentence as a receiver really sends it
    // The sentence a receiver sends: the corrected text for typos, else as printed.
    const std::string &sentence() const { return verdict == "typo" ? corrected : printed; }
};

// Empty when the shared folder is absent (callers skip).
std::vector<SpecExample> loadSpecExamples();
std::string sharedDir();

} // namespace gnss::test
