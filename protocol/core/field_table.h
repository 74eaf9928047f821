#pragma once
// Field tables: a message that is a plain list of typed fields, described once.
//
// Each row names the member, the name refusals give the field ("field 3 (HDOP): not a number")
// and the JSON key. The fields follow one another in the sentence in the rows' order (a latitude
// or a longitude takes two: value and hemisphere), and the JSON lists them in the same order.
// The same rows read the sentence (decodeMessage / readFields), write the message's JSON
// (writeFieldsJson) and, where a dialect has an encoder, tell it how each field is printed
// (decimals, range). A message that is nothing but its rows derives from FieldMessage and is
// decoded by decodeMessage<M>.
#include "core/decode_with.h"
#include "core/field_reader.h"
#include "core/json_writer.h"
#include "core/message.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

namespace gnss {

// How an encoder prints a number: the decimals of a real, and the range a value must lie in
// where the encoder checks one (the NVS output encoders do).
struct FieldLayout {
    int decimals = 0;
    double min = 0, max = 0;
};

// A real written as ddmm.mmmm (dddmm.mmmm) and a hemisphere letter: two fields.
enum class FieldForm : std::uint8_t { Plain, Latitude, Longitude };

template <class M> struct FieldRow {
    using Member =
            std::variant<std::optional<double> M::*, std::optional<int> M::*,
                         std::optional<std::int64_t> M::*, std::optional<char> M::*,
                         std::optional<TimeOfDay> M::*, std::optional<std::string_view> M::*>;
    Member member;
    const char *name;     // in refusals and encoder errors
    std::string_view key; // in JSON
    FieldLayout layout = {};
    FieldForm form = FieldForm::Plain;
};

namespace detail {

inline void readField(FieldReader &r, std::optional<double> &v, std::size_t i, const char *name,
                      FieldForm form) {
    v = form == FieldForm::Latitude    ? r.latitude(i, name)
        : form == FieldForm::Longitude ? r.longitude(i, name)
                                       : r.real(i, name);
}
inline void readField(FieldReader &r, std::optional<int> &v, std::size_t i, const char *name,
                      FieldForm) {
    v = r.integer(i, name);
}
inline void readField(FieldReader &r, std::optional<std::int64_t> &v, std::size_t i,
                      const char *name, FieldForm) {
    v = r.integer64(i, name);
}
inline void readField(FieldReader &r, std::optional<char> &v, std::size_t i, const char *name,
                      FieldForm) {
    v = r.letter(i, name);
}
inline void readField(FieldReader &r, std::optional<TimeOfDay> &v, std::size_t i, const char *name,
                      FieldForm) {
    v = r.time(i, name);
}

inline void readField(FieldReader &r, std::optional<std::string_view> &v, std::size_t i,
                      const char *, FieldForm) {
    v = r.str(i); // text as printed: never a problem
}

} // namespace detail

// Reads each row's field into `m`, the first row from field 0.
template <class M, class Rows> void readFields(FieldReader &r, M &m, const Rows &rows) {
    std::size_t i = 0;
    for (const auto &row : rows) {
        std::visit([&](auto p) { detail::readField(r, m.*p, i, row.name, row.form); }, row.member);
        i += row.form == FieldForm::Plain ? 1 : 2;
    }
}

// One JSON object: each row's key and value, in the rows' order (null where empty).
template <class M, class Rows> void writeFieldsJson(JsonWriter &w, const M &m, const Rows &rows) {
    w.beginObject();
    for (const auto &row : rows) std::visit([&](auto p) { w.field(row.key, m.*p); }, row.member);
    w.endObject();
}

// The base of a message that is just its rows: M declares `static const MessageType kType`,
// `static const FieldRow<M> kFields[N]` and `static constexpr std::size_t kRequired` (the fields
// a sentence must have); its JSON is its rows'.
template <class M> struct FieldMessage : Message {
    FieldMessage() : Message(M::kType) {}
    void writeJson(JsonWriter &w) const override {
        writeFieldsJson(w, static_cast<const M &>(*this), M::kFields);
    }
};

// The decoder of a FieldMessage, for a dialect's sentence table: at least kRequired fields, then
// every row read in order; the message is delivered, or the first problem reported.
template <class M> bool decodeMessage(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<M>(s, ctx, M::kRequired,
                         [](FieldReader &r, M &m) { readFields(r, m, M::kFields); });
}

} // namespace gnss
