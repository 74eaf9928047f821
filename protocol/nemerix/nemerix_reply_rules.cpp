// What the VT002 answers to each command. The spec documents replies only for PNMRX600 (the
// software version) and PNMRX603 (the settings, messages 0 to 4); every other command is taken
// silently, so it counts as sent once written. Replies are matched on the number after the
// prefix, so a renamed prefix ($PXYZW600) is recognised too.
#include "nemerix_dialect_parts.h"

namespace gnss::nemerix {

namespace {

bool isNemerixReply(const Sentence &reply, std::string_view number) {
    const auto a = reply.address();
    return reply.proprietary() && a.size() > number.size() &&
           a.substr(a.size() - number.size()) == number;
}

bool hasFields(const Sentence &s) {
    for (std::size_t i = 0; i < s.fieldCount(); ++i)
        if (!s.field(i).empty()) return true;
    return false;
}

ReplyVerdict versionReply(const Sentence &, const Sentence &reply, ReplyProgress &progress) {
    if (!isNemerixReply(reply, "600") || !hasFields(reply)) return ReplyVerdict::NotMine;
    ++progress.received;
    return ReplyVerdict::Accepted;
}

// Messages 0..4, in order; the answer is complete with message 4.
ReplyVerdict settingsReply(const Sentence &, const Sentence &reply, ReplyProgress &progress) {
    if (!isNemerixReply(reply, "603") || !hasFields(reply)) return ReplyVerdict::NotMine;
    progress.expected = 5;
    ++progress.received;
    return reply.field(0) == "4" ? ReplyVerdict::Accepted : ReplyVerdict::Partial;
}

constexpr ReplyRule kReplyRules[] = {
        {"PNMRX600", "", versionReply, 1000, 2, CommandEffect::None, "$PNMRX600,<version fields>"},
        {"PNMRX603", "", settingsReply, 2000, 2, CommandEffect::None,
         "five $PNMRX603 messages, numbered 0 to 4"},
        {"PNMRX100", "", nullptr, 0, 0, CommandEffect::ChangesBaud,
         "no reply; the port switches to the new speed (protocol 1 leaves NMEA)"},
        {"PNMRX101", "", nullptr, 0, 0, CommandEffect::ResetsReceiver,
         "no reply; setting the ECEF position restarts the receiver"},
        {"PNMRX103", "", nullptr, 0, 0, CommandEffect::ChangesOutput, "no reply"},
        {"PNMRX104", "", nullptr, 0, 0, CommandEffect::ResetsReceiver,
         "no reply; setting the LLA position restarts the receiver"},
        {"PNMRX106", "", nullptr, 0, 0, CommandEffect::None, "no reply"},
        {"PNMRX107", "", nullptr, 0, 0, CommandEffect::ChangesOutput,
         "no reply; mode 1 or 3 sends the requested PNMRX300-304 messages at once"},
        {"PNMRX108", "", nullptr, 0, 0, CommandEffect::ChangesOutput, "no reply"},
        {"PNMRX110", "", nullptr, 0, 0, CommandEffect::None, "no reply"},
        {"PNMRX111", "", nullptr, 0, 0, CommandEffect::ResetsReceiver,
         "no reply; the receiver restarts"},
        {"PNMRX112", "", nullptr, 0, 0, CommandEffect::None, "no reply"},
        {"PNMRX113", "", nullptr, 0, 0, CommandEffect::None,
         "no reply; data extraction and fixes stop until a reset"},
        {"PNMRX300", "", nullptr, 0, 0, CommandEffect::None, "no reply"},
        {"PNMRX601", "", nullptr, 0, 0, CommandEffect::ChangesProtocol,
         "no reply; the receiver enters ISP (firmware download) mode"},
};

} // namespace

std::span<const ReplyRule> replyRules() {
    return kReplyRules;
}

} // namespace gnss::nemerix
