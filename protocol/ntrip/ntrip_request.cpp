#include "ntrip/ntrip_request.h"

#include "ntrip/base64.h"

namespace gnss::ntrip {

namespace {

bool hasControl(std::string_view s) {
    for (char c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) return true;
    return false;
}

} // namespace

std::string checkMountpoint(std::string_view m) {
    if (hasControl(m)) return "a mountpoint cannot hold control characters";
    for (char c : m)
        if (c == ' ' || c == '?' || c == '#')
            return std::string("a mountpoint cannot hold '") + c + "'";
    if (!m.empty() && m.front() == '/') return "give the mountpoint without its leading '/'";
    return {};
}

std::string basicAuthorization(std::string_view user, std::string_view password) {
    std::string pair(user);
    pair.push_back(':');
    pair.append(password);
    return "Basic " + base64Encode(pair);
}

std::string buildRequest(const RequestTarget &t, std::string &error) {
    error = checkMountpoint(t.mountpoint);
    if (!error.empty()) return {};
    // Basic authentication joins the two with ':', so the user name cannot hold one. Control
    // characters in either would never survive a caster's parser.
    if (t.user.find(':') != std::string::npos) {
        error = "a user name cannot hold ':' (Basic authentication)";
        return {};
    }
    if (hasControl(t.user) || hasControl(t.password)) {
        error = "the user name or password holds control characters";
        return {};
    }
    if (t.version == NtripVersion::V2 &&
        (t.host.empty() || hasControl(t.host) || t.host.find(' ') != std::string::npos)) {
        error = "NTRIP 2 needs the caster's host name for the Host header";
        return {};
    }
    const bool v2 = t.version == NtripVersion::V2;
    std::string r = "GET /";
    r += t.mountpoint;
    r += v2 ? " HTTP/1.1\r\n" : " HTTP/1.0\r\n";
    if (v2) {
        const bool ipv6 = t.host.find(':') != std::string::npos;
        r += "Host: ";
        r += ipv6 ? "[" + t.host + "]" : t.host;
        r += ":" + std::to_string(t.port) + "\r\n";
        r += "Ntrip-Version: Ntrip/2.0\r\n";
    }
    r += "User-Agent: ";
    r += kUserAgent;
    r += "\r\n";
    if (!t.user.empty()) r += "Authorization: " + basicAuthorization(t.user, t.password) + "\r\n";
    if (v2) r += "Connection: close\r\n";
    r += "\r\n";
    return r;
}

} // namespace gnss::ntrip
