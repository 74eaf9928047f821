// What the VT002 answers to each command. The spec documents replies only for PNMRX600 (the
// software version) and PNMRX603 (the settings, messages 0 to 4); every other command is taken
// silently, so it counts as sent once written. Replies are matched on the number after the
// prefix, so a renamed prefix ($PXYZW600) is recognised too.
#include "nemerix/nemerix_dialect_parts.h"

namespace gnss::nemerix {

namespace {

bool hasFields(const Sentence &s) {
    for (std::size_t i = 0; i < s.fieldCount(); ++i)
        if (!s.field(i).empty()) return true;
    return false;
}

// A proprietary sentence with fields whose address ends in `number` ("600").
bool isNemerixReply(const Sentence &reply, std::string_view number) {
    const auto a = reply.address();
    return reply.proprietary() && a.size() > number.size() &&
           a.substr(a.size() - number.size()) == number && hasFields(reply);
}

ReplyVerdict versionReply(const Sentence &, const Sentence &reply, ReplyProgress &progress) {
    if (!isNemerixReply(reply, "600")) return ReplyVerdict::NotMine;
    ++progress.received;
    return ReplyVerdict::Accepted;
}

// Messages 0..4, in order; the answer is complete with message 4.
ReplyVerdict settingsReply(const Sentence &, const Sentence &reply, ReplyProgress &progress) {
    if (!isNemerixReply(reply, "603")) return ReplyVerdict::NotMine;
    progress.expected = 5;
    ++progress.received;
    return reply.field(0) == "4" ? ReplyVerdict::Accepted : ReplyVerdict::Partial;
}

// A command the receiver takes without a word: it counts as sent once written.
constexpr ReplyRule silent(std::string_view command, CommandEffect effect,
                           std::string_view description = "no reply") {
    return {command, "", nullptr, 0, 0, effect, description};
}

constexpr ReplyRule kReplyRules[] = {
        {"PNMRX600", "", versionReply, 1000, 2, CommandEffect::None, "$PNMRX600,<version fields>"},
        {"PNMRX603", "", settingsReply, 2000, 2, CommandEffect::None,
         "five $PNMRX603 messages, numbered 0 to 4"},
        silent("PNMRX100", CommandEffect::ChangesBaud,
               "no reply; the port switches to the new speed (protocol 1 leaves NMEA)"),
        silent("PNMRX101", CommandEffect::ResetsReceiver,
               "no reply; setting the ECEF position restarts the receiver"),
        silent("PNMRX103", CommandEffect::ChangesOutput),
        silent("PNMRX104", CommandEffect::ResetsReceiver,
               "no reply; setting the LLA position restarts the receiver"),
        silent("PNMRX106", CommandEffect::None),
        silent("PNMRX107", CommandEffect::ChangesOutput,
               "no reply; mode 1 or 3 sends the requested PNMRX300-304 messages at once"),
        silent("PNMRX108", CommandEffect::ChangesOutput),
        silent("PNMRX110", CommandEffect::None),
        silent("PNMRX111", CommandEffect::ResetsReceiver, "no reply; the receiver restarts"),
        silent("PNMRX112", CommandEffect::None),
        silent("PNMRX113", CommandEffect::None,
               "no reply; data extraction and fixes stop until a reset"),
        silent("PNMRX300", CommandEffect::None),
        silent("PNMRX601", CommandEffect::ChangesProtocol,
               "no reply; the receiver enters ISP (firmware download) mode"),
};

} // namespace

std::span<const ReplyRule> replyRules() {
    return kReplyRules;
}

} // namespace gnss::nemerix
