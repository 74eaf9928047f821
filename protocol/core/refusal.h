#pragma once
// Refusal: why a value or a request is refused, as a person reads it, in two forms. `text` is the
// English sentence the command line prints; `form` is the same sentence as a template with %1,
// %2 ... for `args` ("%1: %2 is out of range; accepted: %3"), marked for translation in context
// "Refusal" where it is written, so that the GUI shows it in the user's language with the same
// arguments (config/refusal_text.h). A refusal made from a plain sentence has no form and is shown
// as written.
#include <string>
#include <vector>

// The core has no Qt: the marker lupdate looks for, expanding to the text itself (the same
// definition as Qt's, so that a file including both sees one macro).
#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(scope, x) x
#endif

namespace gnss {

struct Refusal {
    std::string text;           // English, complete; empty: not refused
    const char *form = nullptr; // the template of `text`, or nullptr
    std::vector<std::string> args;

    Refusal() = default;
    // A plain sentence (no translation). There is no constructor from a literal: a template
    // passed where a refusal is expected must go through refusal(), never lose its form.
    Refusal(std::string plain) : text(std::move(plain)) {}
    bool empty() const { return text.empty(); }
    operator const std::string &() const { return text; }
};

// A refusal from a template marked QT_TRANSLATE_NOOP("Refusal", ...) and its arguments.
Refusal refusal(const char *form, std::vector<std::string> args);

} // namespace gnss
