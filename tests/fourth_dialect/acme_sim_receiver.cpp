#include "acme_sim_receiver.h"

#include "acme_dialect.h"
#include "sim/dialect_receiver.h"
#include "sim/standard_output.h"

namespace gnss::acme {
namespace {

constexpr const char *kModel = "AX-1";
constexpr const char *kFirmware = "4.2.0";

class AcmeReceiver : public sim::DialectReceiver {
public:
    explicit AcmeReceiver(const sim::SimOptions &options)
        : DialectReceiver(acme::dialect(), options) {
        style_.numbering = sim::Numbering::Nmea41;
    }

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view) override {
        if (!decoded) return;
        if (const auto *v = message_cast<Version>(*decoded); v && v->request) {
            Version me;
            me.model = kModel;
            me.firmware = kFirmware;
            reply(s, encodeVersion(me));
        } else if (const auto *set = message_cast<Setting>(*decoded)) {
            answer(s, *set);
        } else if (const auto *a = message_cast<Action>(*decoded)) {
            act(s, *a);
        }
    }

    void onEpoch(const sim::SkySnapshot &snap) override {
        const sim::EpochTime t{utcSecondOfDay(), utcDate()};
        send(sim::ggaSentence(snap, t, style_));
        send(sim::rmcSentence(snap, t, style_));
        for (const std::string &l : sim::gsaSentences(snap, style_)) send(l);
        for (const std::string &l : sim::gsvSentences(snap, style_)) send(l);
        Status status;
        status.fix = snap.fix == sim::FixKind::None ? 0 : 2;
        status.used = snap.used;
        status.temperature = 41.5;
        send(encodeStatus(status));
    }

    void onReset(sim::ResetKind kind) override {
        if (kind == sim::ResetKind::PowerCycle) restoreFromFlash();
    }

private:
    // PACMC sets (and is echoed with the value in force), PACMQ reads; an unknown name is
    // refused with PACMN.
    void answer(const Sentence &s, const Setting &m) {
        const std::string key = "acme." + std::string(m.name);
        if (!findSetting(dialect().settings, key)) {
            reply(s, encodeRefusal(m.name));
            return;
        }
        const double interval = epochInterval();
        if (m.kind == 'C') store_.apply(m);
        const std::string keys[] = {key};
        const EncodeResult r = store_.report(keys);
        if (!r.ok()) return;
        const bool baud = key == "acme.BAUD" && m.kind == 'C';
        reply(s, r.sentences.front(), baud ? portSpeed() : 0);
        if (epochInterval() != interval) rescheduleEpochs();
    }

    void act(const Sentence &s, const Action &a) {
        const std::string what(a.what);
        if (what == "SAVE")
            store_.save();
        else if (what == "DEFAULTS")
            store_.saveDefaults();
        else if (what != "COLD" && what != "HOT")
            return;
        Action done;
        done.what = a.what;
        done.ok = true;
        reply(s, encodeAction(done));
        if (what == "COLD") reset(sim::ResetKind::Cold);
        if (what == "HOT") reset(sim::ResetKind::Hot);
    }

    sim::StandardStyle style_;
};

} // namespace

std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options) {
    return std::make_unique<AcmeReceiver>(options);
}

} // namespace gnss::acme
