#include "ntrip/response_head.h"

#include "ntrip/text_util.h"

#include <array>

namespace gnss::ntrip {

namespace {

// The status lines a caster may send; a first line that cannot become one of them is not a
// reply head, and saying so at once spares waiting for a newline in binary noise.
constexpr std::array<std::string_view, 4> kStatusPrefixes = {"ICY ", "HTTP/", "SOURCETABLE ",
                                                             "ERROR"};

bool couldBeStatusLine(std::string_view partial) {
    for (std::string_view p : kStatusPrefixes) {
        const std::size_t n = std::min(partial.size(), p.size());
        if (partial.substr(0, n) == p.substr(0, n)) return true;
    }
    return false;
}

bool isPrintable(char c) {
    return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F;
}

std::string_view withoutCr(std::string_view line) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

// Three digits followed by a space or the end: the status code; 0 otherwise.
int parseCode(std::string_view s) {
    if (s.size() < 3 || (s.size() > 3 && s[3] != ' ')) return 0;
    int code = 0;
    for (int i = 0; i < 3; ++i) {
        if (s[i] < '0' || s[i] > '9') return 0;
        code = code * 10 + (s[i] - '0');
    }
    return code;
}

ReplyKind kindForCode(int code) {
    switch (code) {
    case 401: return ReplyKind::Unauthorized;
    case 404: return ReplyKind::NotFound;
    default: return ReplyKind::OtherStatus;
    }
}

// "Name: value" with a token for a name: what an NTRIP 1 caster may put after ICY 200 OK.
bool looksLikeHeader(std::string_view line) {
    const auto colon = line.find(':');
    if (colon == std::string_view::npos || colon == 0) return false;
    for (std::size_t i = 0; i < colon; ++i) {
        const char c = line[i];
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
              c == '-' || c == '_'))
            return false;
    }
    for (char c : line.substr(colon + 1))
        if (!isPrintable(c) && c != '\t') return false;
    return true;
}

bool startsHeaderName(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

} // namespace

std::string ResponseHead::revisionText() const {
    switch (style) {
    case ReplyStyle::Icy: return "NTRIP 1 (ICY)";
    case ReplyStyle::SourceTable: return "NTRIP 1 (SOURCETABLE)";
    case ReplyStyle::Error: return "NTRIP 1 (ERROR line)";
    case ReplyStyle::Http:
        if (startsWithNoCase(ntripVersion, "Ntrip/2")) return "NTRIP 2 (HTTP/" + httpVersion + ")";
        return "HTTP/" + httpVersion;
    case ReplyStyle::Unknown: break;
    }
    return "unknown";
}

void ResponseHeadParser::feed(std::string_view bytes, std::string &body) {
    std::size_t i = 0;
    for (; i < bytes.size() && state_ != State::Body; ++i) {
        const char c = bytes[i];
        ++headBytes_;
        switch (state_) {
        case State::Status: statusByte(c); break;
        case State::Headers: headerByte(c); break;
        case State::IcyHeaders: icyHeaderByte(c, body); break;
        case State::Body: break;
        }
    }
    // What follows a reply that is no NTRIP reply means nothing: it is dropped, not passed on.
    if (i < bytes.size() && head_.kind != ReplyKind::NotNtrip) body.append(bytes.substr(i));
}

void ResponseHeadParser::statusByte(char c) {
    if (c == '\n') {
        const std::string line = std::move(line_);
        line_.clear();
        parseStatusLine(withoutCr(line));
        return;
    }
    line_.push_back(c);
    const bool crAtEnd = c == '\r';
    if ((!isPrintable(c) && !crAtEnd) || line_.size() > kMaxLine || !couldBeStatusLine(line_))
        notNtrip();
}

void ResponseHeadParser::parseStatusLine(std::string_view line) {
    head_.statusLine = printableCopy(line, 200);
    if (line.find('\r') != std::string_view::npos) return notNtrip();
    if (line.substr(0, 5) == "ERROR") {
        head_.style = ReplyStyle::Error;
        head_.kind = ReplyKind::CasterError;
        state_ = State::Body; // nothing after it means anything
        return;
    }
    int code = 0;
    if (line.substr(0, 4) == "ICY ") {
        head_.style = ReplyStyle::Icy;
        code = parseCode(line.substr(4));
        state_ = State::IcyHeaders;
    } else if (line.substr(0, 12) == "SOURCETABLE ") {
        head_.style = ReplyStyle::SourceTable;
        code = parseCode(line.substr(12));
        state_ = State::Headers;
    } else if (line.substr(0, 5) == "HTTP/") {
        head_.style = ReplyStyle::Http;
        const auto space = line.find(' ');
        if (space != std::string_view::npos) {
            head_.httpVersion = std::string(line.substr(5, space - 5));
            code = parseCode(line.substr(space + 1));
        }
        state_ = State::Headers;
    }
    if (code == 0) return notNtrip();
    head_.statusCode = code;
    if (code != 200)
        head_.kind = kindForCode(code);
    else if (head_.style == ReplyStyle::Icy)
        head_.kind = ReplyKind::Data;
    else if (head_.style == ReplyStyle::SourceTable)
        head_.kind = ReplyKind::SourceTable;
    // HTTP 200: the Content-Type header decides, at the end of the head.
}

void ResponseHeadParser::headerByte(char c) {
    if (headBytes_ > kMaxHead) return notNtrip();
    if (c != '\n') {
        line_.push_back(c);
        if (line_.size() > kMaxLine) notNtrip();
        return;
    }
    const std::string line = std::move(line_);
    line_.clear();
    const std::string_view l = withoutCr(line);
    if (l.empty())
        endOfHead();
    else
        parseHeaderLine(l);
}

void ResponseHeadParser::icyHeaderByte(char c, std::string &body) {
    // After "ICY 200 OK" most casters send data at once; a few send header lines and a blank
    // line first. A line is taken as a header only while it reads like one; the first byte
    // that cannot belong to a header line hands everything held so far on as body.
    auto handOver = [&] {
        body.append(line_);
        line_.clear();
        endOfHead();
    };
    if (c == '\n') {
        const std::string_view l = withoutCr(line_);
        if (l.empty()) {
            line_.clear();
            return endOfHead();
        }
        if (looksLikeHeader(l)) {
            parseHeaderLine(l);
            line_.clear();
            return;
        }
        line_.push_back(c);
        return handOver();
    }
    line_.push_back(c);
    const bool first = line_.size() == 1;
    const bool fits = first ? (startsHeaderName(c) || c == '\r')
                            : ((isPrintable(c) || c == '\t' || c == '\r') && line_[0] != '\r');
    if (!fits || line_.size() > kMaxLine || headBytes_ > kMaxHead) handOver();
}

void ResponseHeadParser::parseHeaderLine(std::string_view line) {
    const auto colon = line.find(':');
    if (colon == std::string_view::npos) {
        ++head_.badHeaderLines;
        return;
    }
    const std::string_view name = trim(line.substr(0, colon));
    const std::string_view value = trim(line.substr(colon + 1));
    if (head_.headers.size() < kMaxHeaders)
        head_.headers.emplace_back(printableCopy(name, kMaxLine), printableCopy(value, kMaxLine));
    if (equalsNoCase(name, "Content-Type")) {
        // Printable, as every text of the head: it is shown in messages ("answered with %1").
        head_.contentType =
                toLower(printableCopy(trim(value.substr(0, value.find(';'))), kMaxLine));
    } else if (equalsNoCase(name, "Transfer-Encoding")) {
        // "gzip, chunked": chunked is always the last coding when present.
        const auto comma = value.rfind(',');
        head_.chunked = equalsNoCase(
                trim(comma == std::string_view::npos ? value : value.substr(comma + 1)), "chunked");
    } else if (equalsNoCase(name, "Content-Length")) {
        head_.contentLength = parseUnsigned(value);
    } else if (equalsNoCase(name, "Ntrip-Version")) {
        head_.ntripVersion = printableCopy(value, 64);
    }
}

void ResponseHeadParser::endOfHead() {
    state_ = State::Body;
    if (head_.kind != ReplyKind::Incomplete) return;
    if (head_.statusCode != 200) return notNtrip();
    const std::string &t = head_.contentType;
    if (t.empty() || t == "gnss/data" || t == "application/octet-stream")
        head_.kind = ReplyKind::Data;
    else if (t == "gnss/sourcetable")
        head_.kind = ReplyKind::SourceTable;
    else
        head_.kind = ReplyKind::UnexpectedContent;
}

void ResponseHeadParser::notNtrip() {
    if (head_.statusLine.empty()) head_.statusLine = printableCopy(withoutCr(line_), 200);
    head_.kind = ReplyKind::NotNtrip;
    line_.clear();
    state_ = State::Body;
}

void ResponseHeadParser::finish() {
    if (state_ == State::Status) {
        if (line_.empty()) return; // nothing arrived: still Incomplete
        const std::string line = std::move(line_);
        line_.clear();
        parseStatusLine(withoutCr(line));
    }
    if (state_ == State::Headers && !line_.empty()) {
        const std::string line = std::move(line_);
        line_.clear();
        const std::string_view l = withoutCr(line);
        if (!l.empty()) parseHeaderLine(l);
    }
    if (state_ != State::Body) {
        line_.clear();
        endOfHead();
    }
}

} // namespace gnss::ntrip
