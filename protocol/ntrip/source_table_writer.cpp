// Source tables written: STR records from StreamEntry, ENDSOURCETABLE at the end.
#include "ntrip/source_table_writer.h"

#include <cstdio>
#include <variant>

namespace gnss::ntrip {

namespace {

// `s` as one field: no control characters, and no ';' unless it is the last field.
void appendTableField(std::string &out, std::string_view s, bool last) {
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7F) continue;
        out.push_back(c == ';' && !last ? ',' : c);
    }
}

std::string tableNumber(const std::optional<int> &v) {
    return v ? std::to_string(*v) : std::string();
}

std::string tableDegrees(const std::optional<double> &v) {
    if (!v) return {};
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", *v);
    return buf;
}

} // namespace

std::string streamRecord(const StreamEntry &e) {
    std::string out = "STR";
    const auto fields = streamFields();
    for (std::size_t i = 0; i < fields.size(); ++i) {
        out.push_back(';');
        const bool last = i + 1 == fields.size();
        std::visit(
                [&](auto member) {
                    const auto &v = e.*member;
                    using V = std::decay_t<decltype(v)>;
                    if constexpr (std::is_same_v<V, std::string>)
                        appendTableField(out, v, last);
                    else if constexpr (std::is_same_v<V, std::optional<int>>)
                        out += tableNumber(v);
                    else if constexpr (std::is_same_v<V, std::optional<double>>)
                        out += tableDegrees(v);
                    else if (member == &StreamEntry::fee)
                        out += v ? "Y" : "N";
                    else
                        out += v ? "1" : "0";
                },
                fields[i].member);
    }
    out += "\r\n";
    return out;
}

std::string writeSourceTable(std::span<const StreamEntry> streams) {
    std::string out;
    for (const StreamEntry &e : streams) out += streamRecord(e);
    out += "ENDSOURCETABLE\r\n";
    return out;
}

} // namespace gnss::ntrip
