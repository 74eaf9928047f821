#pragma once
// ACME AX-1: a receiver family that exists only in the tests. It is written the way a fourth
// vendor would be added (its own sentences, settings, a command with a reply rule, actions,
// presets, link speeds, roles and a simulated receiver, all in this folder) and registered with
// one line (acme_registry.h), to prove that every surface of the program takes a new family
// without a change anywhere else.
//
//   $PACMS,<fix 0-2>,<satellites used>,<temperature C>*hh   status, every epoch
//   $PACMV*hh                                               identity request (the probe)
//   $PACMV,<model>,<firmware>*hh                            identity
//   $PACMC,<NAME>,<value>*hh                                set a setting; echoed as taken
//   $PACMQ,<NAME>*hh                                        read a setting: answered by PACMC
//   $PACMN,<NAME>*hh                                        the receiver refuses a PACMC
//   $PACMA,<SAVE|DEFAULTS|COLD|HOT>*hh                      actions, answered by PACMA,<x>,OK
#include "core/dialect.h"
#include "core/field_table.h"
#include "core/message.h"

#include <optional>
#include <string>
#include <string_view>

namespace gnss::acme {

// A plain list of fields: its rows (acme_dialect.cpp) decode it and write its JSON.
struct Status : FieldMessage<Status> {
    static const MessageType kType;
    static const FieldRow<Status> kFields[3];
    static constexpr std::size_t kRequired = 3;
    std::optional<int> fix, used;
    std::optional<double> temperature;
};

struct Version : Message {
    static const MessageType kType;
    Version() : Message(kType) {}
    bool request = false;
    std::optional<std::string_view> model, firmware;
    void writeJson(JsonWriter &w) const override;
};

// PACMC (a setting written, or its value reported), PACMQ (a read), PACMN (a refusal).
struct Setting : Message {
    static const MessageType kType;
    Setting() : Message(kType) {}
    char kind = 'C'; // C, Q or N
    std::string_view name;
    std::optional<std::string_view> value;
    void writeJson(JsonWriter &w) const override;
};

struct Action : Message {
    static const MessageType kType;
    Action() : Message(kType) {}
    std::string_view what;
    bool ok = false; // the receiver's answer ("PACMA,SAVE,OK")
    void writeJson(JsonWriter &w) const override;
};

// The receiver's own sentences, from their messages (what the simulated receiver sends).
std::string encodeStatus(const Status &m);
std::string encodeVersion(const Version &m);
std::string encodeAction(const Action &m);
std::string encodeRefusal(std::string_view name);

const Dialect &dialect();

} // namespace gnss::acme
