// CasterRequestParser: an NTRIP client's request head, read as a caster reads it.
#include "ntrip/caster_request.h"

#include "ntrip/base64.h"
#include "ntrip/text_util.h"

namespace gnss::ntrip {

namespace {

// An HTTP token (method, header name): letters, digits and the few marks RFC 9110 allows.
bool isRequestToken(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s) {
        const bool alnum =
                (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (!alnum && std::string_view("!#$%&'*+-.^_`|~").find(c) == std::string_view::npos)
            return false;
    }
    return true;
}

// Control characters (but tab) or bytes above ASCII: nothing a header value may hold here.
bool hasRequestControl(std::string_view s) {
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u >= 0x7F) return true;
    }
    return false;
}

} // namespace

CasterRequestParser::State CasterRequestParser::feed(std::string_view bytes) {
    if (state_ == State::Complete) {
        const std::size_t room = kMaxRest - std::min(kMaxRest, rest_.size());
        rest_.append(bytes.substr(0, room));
        return state_;
    }
    if (state_ == State::Malformed) return state_;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const char c = bytes[i];
        ++headBytes_;
        if (headBytes_ > kMaxHead) {
            fail("the request head is longer than " + std::to_string(kMaxHead) + " bytes");
            return state_;
        }
        if (c != '\n') {
            if (line_.size() >= kMaxLine) {
                fail("a request line is longer than " + std::to_string(kMaxLine) + " bytes");
                return state_;
            }
            line_.push_back(c);
            continue;
        }
        if (!line_.empty() && line_.back() == '\r') line_.pop_back();
        const std::string l = std::move(line_);
        line_.clear();
        line(l);
        if (state_ == State::Complete) {
            rest_.assign(bytes.substr(i + 1, kMaxRest));
            return state_;
        }
        if (state_ == State::Malformed) return state_;
    }
    return state_;
}

void CasterRequestParser::line(std::string_view l) {
    if (!sawRequestLine_) {
        if (l.empty()) return; // blank lines before the request line are tolerated (RFC 9112)
        sawRequestLine_ = true;
        requestLine(l);
        return;
    }
    if (l.empty()) {
        state_ = State::Complete;
        return;
    }
    if (l.front() == ' ' || l.front() == '\t') return fail("a folded header line");
    const auto colon = l.find(':');
    if (colon == std::string_view::npos) return fail("a header line without ':'");
    const std::string_view name = l.substr(0, colon);
    if (!isRequestToken(name)) return fail("a header name that is no token");
    const std::string_view value = trim(l.substr(colon + 1));
    if (hasRequestControl(value)) return fail("a header value with control characters");
    if (++request_.headers > kMaxHeaders)
        return fail("more than " + std::to_string(kMaxHeaders) + " header lines");
    header(name, value);
}

void CasterRequestParser::requestLine(std::string_view l) {
    const auto sp1 = l.find(' ');
    const auto sp2 = sp1 == std::string_view::npos ? sp1 : l.find(' ', sp1 + 1);
    if (sp2 == std::string_view::npos || l.find(' ', sp2 + 1) != std::string_view::npos)
        return fail("the request line is not METHOD PATH HTTP/1.x");
    const std::string_view method = l.substr(0, sp1);
    const std::string_view target = l.substr(sp1 + 1, sp2 - sp1 - 1);
    const std::string_view version = l.substr(sp2 + 1);
    if (!isRequestToken(method)) return fail("the request method is no token");
    request_.method = std::string(method);
    if (version != "HTTP/1.0" && version != "HTTP/1.1")
        return fail("the request's protocol is not HTTP/1.0 or HTTP/1.1");
    request_.httpVersion = std::string(version);
    if (target.empty() || target.front() != '/' || hasRequestControl(target))
        return fail("the request path does not start with '/'");
    request_.target = std::string(target);
    std::string_view mount = target.substr(1);
    mount = mount.substr(0, mount.find('?'));
    if (!checkMountpoint(mount).empty()) return fail("the mountpoint " + checkMountpoint(mount));
    request_.mountpoint = std::string(mount);
    if (method != "GET") return fail("only GET is served, not " + printableCopy(method, 16), 405);
}

void CasterRequestParser::header(std::string_view name, std::string_view value) {
    if (equalsNoCase(name, "Authorization")) {
        request_.hasAuthorization = true;
        const auto sp = value.find(' ');
        request_.authScheme = std::string(value.substr(0, sp));
        if (!equalsNoCase(request_.authScheme, "Basic")) return; // not ours: no user
        const std::string_view credentials =
                sp == std::string_view::npos ? std::string_view() : trim(value.substr(sp + 1));
        const auto decoded = base64Decode(credentials);
        if (!decoded || decoded->empty()) return fail("the Basic credentials are not Base64");
        const auto colon = decoded->find(':');
        if (colon == std::string::npos) return fail("the Basic credentials hold no ':'");
        request_.user = decoded->substr(0, colon);
        request_.password = decoded->substr(colon + 1);
    } else if (equalsNoCase(name, "Ntrip-Version")) {
        if (startsWithNoCase(value, "Ntrip/2")) request_.version = NtripVersion::V2;
    } else if (equalsNoCase(name, "User-Agent")) {
        request_.userAgent = std::string(value);
    } else if (equalsNoCase(name, "Host")) {
        request_.host = std::string(value);
    } else if (equalsNoCase(name, "Ntrip-GGA")) {
        request_.ntripGga = std::string(value);
    }
}

void CasterRequestParser::fail(std::string why, int status) {
    state_ = State::Malformed;
    reason_ = printableCopy(why, 200);
    status_ = status;
}

CasterRequestParser parseCasterRequest(std::string_view bytes) {
    CasterRequestParser p;
    p.feed(bytes);
    return p;
}

} // namespace gnss::ntrip
