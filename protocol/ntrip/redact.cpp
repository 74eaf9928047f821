#include "ntrip/redact.h"

#include "ntrip/base64.h"

#include <algorithm>

namespace gnss::ntrip {

namespace {

void replaceAll(std::string &text, std::string_view what) {
    if (what.empty()) return;
    for (std::size_t at = text.find(what); at != std::string::npos;
         at = text.find(what, at + kRedacted.size()))
        text.replace(at, what.size(), kRedacted);
}

} // namespace

std::string redactCredentials(std::string_view text, std::string_view user,
                              std::string_view password) {
    std::string out(text);
    if (user.empty() && password.empty()) return out;
    std::string pair(user);
    pair.push_back(':');
    pair.append(password);
    // The longest forms first, so a shorter one never leaves part of a longer one behind.
    replaceAll(out, base64Encode(pair));
    replaceAll(out, pair);
    if (password.size() >= kMinMaskedPassword) {
        replaceAll(out, password);
        // Its Base64 alone (some clients send it so): padded, then without the padding (the
        // start of a longer encoding).
        std::string b = base64Encode(password);
        replaceAll(out, b);
        b.erase(std::find(b.begin(), b.end(), '='), b.end());
        if (b.size() >= kMinMaskedPassword) replaceAll(out, b);
    }
    return out;
}

bool hasUserInfo(std::string_view host) {
    return host.find('@') != std::string_view::npos;
}

std::string hostForDisplay(std::string_view host) {
    const auto at = host.rfind('@');
    if (at == std::string_view::npos) return std::string(host);
    return std::string(kRedacted) + std::string(host.substr(at));
}

} // namespace gnss::ntrip
