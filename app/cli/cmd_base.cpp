// gnss-cli base: a receiver as an RTK base station, on the settings engine the GUI uses and the
// base-station roles of its dialect (protocol/base): no NVS key is named here.
//
//   gnss-cli base SOURCE status
//   gnss-cli base SOURCE survey (--minutes M | --sigma METRES) [--by-receiver [--input V]]
//                               [--save-site NAME] [--set [SET OPTIONS]]
//   gnss-cli base SOURCE set (--ecef X,Y,Z | --llh LAT,LON,HEIGHT [--msl] | --site NAME)
//                            [--antenna-height H] [--station N] [--rtcm-port N [--rtcm-baud B]]
//                            [--rtcm-interval S] [--save]
//
// Everything typed is checked before the port is opened; a set is verified by reading it back.
// Before any Qt header: core headers have members named emit, which Qt defines as a macro.
#include "base/base_plan.h"
#include "base/base_status.h"
#include "base/position_text.h"
#include "base/receiver_clock.h"
#include "base/survey_in.h"
#include "core/json_writer.h"
#include "state/epoch_assembler.h"

#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "cli/cli_output.h"
#include "cli/event_loop.h"
#include "cli/settings_link.h"
#include "config/dialect_actions.h"
#include "link/sentence_stream.h"
#include "sites/site_store.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <functional>

namespace gnss::cli {
namespace {

using config::SettingsEngine;

void say(const std::string &s) {
    std::fprintf(stderr, "gnss-cli: %s\n", s.c_str());
}

bool number(const std::string &text, double &out) {
    return sites::parseDecimal(text, out);
}

bool integer(const std::string &text, int &out) {
    double v = 0;
    if (!number(text, v) || v != std::floor(v) || std::abs(v) > 1e9) return false;
    out = static_cast<int>(v);
    return true;
}

// What was typed, checked before anything is opened.
struct SetOptions {
    std::optional<wgs84::Ecef> ecef;
    std::optional<wgs84::Geodetic> llh;
    bool msl = false; // llh's height is above sea level: the receiver's geoid separation added
    std::optional<sites::Site> site;
    std::optional<double> antennaHeight;
    base::BaseRequest request;
    bool save = false;
};

struct SurveyOptions {
    base::SurveyGoal goal;
    bool byReceiver = false;
    std::optional<std::string> input;
    std::optional<std::string> saveSite;
    bool set = false;
};

// Reads the options a set takes (a survey with --set takes them too, without a position).
int parseSet(const Args &args, SetOptions &o, bool positionRequired) {
    std::string error;
    int given = 0;
    if (const auto v = args.option("ecef")) {
        ++given;
        o.ecef = base::ecefOf(*v);
        if (!o.ecef) return say("--ecef: expected X,Y,Z in metres, got '" + *v + "'"), 2;
    }
    if (const auto v = args.option("llh")) {
        ++given;
        o.llh = base::parseGeodetic(*v, error);
        if (!o.llh) return say("--llh: " + error), 2;
    }
    o.msl = args.flag("msl");
    if (o.msl && !o.llh)
        return say("--msl says how --llh's height is given: it goes with --llh"), 2;
    if (const auto v = args.option("site")) {
        ++given;
        sites::SiteStore store;
        sites::SiteList list;
        QString why;
        if (!store.load(list, why)) return say(why.toStdString()), 1;
        const auto found = list.lookup(*v);
        if (!found.site) {
            std::string names;
            for (const auto &c : found.candidates) names += (names.empty() ? "" : ", ") + c;
            return say("--site: " +
                       std::string(found.ambiguous ? "several sites start with '"
                                                   : "no site named '") +
                       *v + "'" + (names.empty() ? "" : " (" + names + ")")),
                   2;
        }
        o.site = *found.site;
    }
    if (given > 1) return say("give one of --ecef, --llh and --site"), 2;
    if (positionRequired && given == 0)
        return say("set needs the base's position: --ecef X,Y,Z, --llh LAT,LON,HEIGHT or --site "
                   "NAME"),
               2;
    if (!positionRequired && given > 0)
        return say("a survey finds the position: leave out --ecef, --llh and --site"), 2;
    if (const auto v = args.option("antenna-height")) {
        double h = 0;
        if (!number(*v, h) || h < 0 || h > 100)
            return say("--antenna-height: expected metres from 0 to 100, got '" + *v + "'"), 2;
        o.antennaHeight = h;
    }
    auto intOption = [&](const char *name, std::optional<int> &out) {
        if (const auto v = args.option(name)) {
            int n = 0;
            if (!integer(*v, n))
                return say(std::string("--") + name + ": expected a whole number, got '" + *v +
                           "'"),
                       false;
            out = n;
        }
        return true;
    };
    if (!intOption("station", o.request.station) || !intOption("rtcm-port", o.request.rtcmPort) ||
        !intOption("rtcm-baud", o.request.rtcmPortSpeed) ||
        !intOption("rtcm-interval", o.request.rtcmInterval))
        return 2;
    if (o.request.rtcmPortSpeed && !o.request.rtcmPort)
        return say("--rtcm-baud is the speed of --rtcm-port's port: give --rtcm-port"), 2;
    o.save = args.flag("save");
    return 0;
}

int parseSurvey(const Args &args, SurveyOptions &o) {
    const auto minutes = args.option("minutes");
    const auto sigma = args.option("sigma");
    if (!minutes && !sigma) return say("survey needs --minutes M or --sigma METRES"), 2;
    if (minutes) {
        double m = 0;
        if (!number(*minutes, m) || m <= 0 || m > 24 * 60)
            return say("--minutes: expected minutes from 0 to 1440, got '" + *minutes + "'"), 2;
        o.goal.seconds = m * 60;
    }
    if (sigma) {
        double s = 0;
        if (!number(*sigma, s) || s <= 0 || s > 100)
            return say("--sigma: expected metres above 0 (up to 100), got '" + *sigma + "'"), 2;
        o.goal.accuracy = s;
    }
    o.byReceiver = args.flag("by-receiver");
    if (o.byReceiver && o.goal.accuracy)
        return say("--by-receiver: the receiver averages for a time: give --minutes, not --sigma"),
               2;
    if (o.byReceiver && std::fmod(*o.goal.seconds, 60) != 0)
        return say("--by-receiver: the receiver averages whole minutes"), 2;
    o.input = args.option("input");
    if (o.input && !o.byReceiver)
        return say("--input is what the receiver averages: it goes with --by-receiver"), 2;
    o.saveSite = args.option("save-site");
    if (o.saveSite)
        if (const std::string why = sites::nameProblem(*o.saveSite); !why.empty())
            return say("--save-site: " + why), 2;
    o.set = args.flag("set");
    return 0;
}

// The receiver's epochs with a position, as they come.
class FixWatcher {
public:
    explicit FixWatcher(link::Connection &c) : assembler_(c.stream()->dialect()) {
        QObject::connect(c.stream(), &link::SentenceStream::sentenceDecoded, &context_,
                         [this, &c](const SentenceEvent &ev) {
                             if (!ev.message) return;
                             assembler_.setDialect(c.stream()->dialect());
                             assembler_.add(ev.sentence, *ev.message,
                                            [this](const Epoch &e) { onEpoch(e); });
                         });
    }
    std::function<void(const base::OwnFix &, const Epoch &)> onFix;
    std::optional<base::OwnFix> last;
    std::optional<double> geoidSep;

    // Waits up to `ms` for a fix; the last one (or none).
    std::optional<base::OwnFix> wait(int ms) {
        if (last) return last;
        QEventLoop loop;
        QTimer::singleShot(ms, &loop, &QEventLoop::quit);
        auto keep = onFix;
        onFix = [&](const base::OwnFix &f, const Epoch &e) {
            if (keep) keep(f, e);
            loop.quit();
        };
        loop.exec();
        onFix = keep;
        return last;
    }

    // The receiver's clock, seconds: its epochs' UTC (across midnight), or the host's while it
    // gives none. A survey of M minutes is M minutes of the receiver's positions, whatever the
    // pace they arrive at (a simulator run faster than real time, a replay).
    double clock() const { return clock_.timed() ? clock_.seconds() : host_.elapsed() / 1000.0; }
    // Waits up to `ms` for an epoch that carries the time (then clock() is the receiver's).
    void waitForTime(int ms) {
        QElapsedTimer t;
        t.start();
        while (!clock_.timed() && t.elapsed() < ms)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    }

private:
    void onEpoch(const Epoch &e) {
        clock_.add(e.time);
        const auto position = e.position();
        if (!position) return;
        if (e.geoidSep) geoidSep = e.geoidSep;
        const base::OwnFix f{*position, std::string(toString(e.fix))};
        last = f;
        if (onFix) onFix(f, e);
    }
    QObject context_;
    EpochAssembler assembler_;
    QElapsedTimer host_ = [] {
        QElapsedTimer t;
        t.start();
        return t;
    }();
    base::ReceiverClock clock_;
};

std::function<std::optional<std::string>(std::string_view)> knownOf(const SettingsEngine &e) {
    return [&e](std::string_view key) { return e.receiverValue(key); };
}

void printStatus(const base::BaseRoles &roles, const SettingsEngine &engine,
                 const std::optional<base::OwnFix> &own) {
    const base::BaseStatus s = base::baseStatus(roles, knownOf(engine), own);
    printJson([&](JsonWriter &w) {
        w.beginObject().key("status");
        base::writeJson(w, s);
        w.endObject();
    });
    if (s.beyondThreshold)
        say("warning: the base position is " + std::to_string(std::lround(*s.distance)) +
            " m from the receiver's own fix, past its threshold of " +
            std::to_string(std::lround(*s.threshold)) + " m: it sends no corrections");
}

// The position a set asks for, the antenna height added (and the geoid separation for --msl).
std::optional<wgs84::Ecef> positionOf(const SetOptions &o, FixWatcher &fixes) {
    if (o.ecef) return base::raised(*o.ecef, o.antennaHeight.value_or(0));
    if (o.site) {
        sites::Site s = *o.site;
        if (o.antennaHeight) s.antennaHeight = *o.antennaHeight;
        return s.antennaReferenceEcef();
    }
    if (!o.llh) return std::nullopt;
    wgs84::Geodetic g = *o.llh;
    if (o.msl) {
        fixes.wait(10000);
        if (!fixes.geoidSep) {
            say("--msl: the receiver gave no geoid separation within 10 s; give an ellipsoidal "
                "height instead");
            return std::nullopt;
        }
        g.height += *fixes.geoidSep;
    }
    g.height += o.antennaHeight.value_or(0);
    return wgs84::toEcef(g);
}

int applyBase(SettingsEngine &engine, const base::BaseRoles &roles, const SetOptions &o,
              FixWatcher &fixes) {
    const base::BasePlan plan = base::planBase(roles, o.request, knownOf(engine));
    if (!plan.ok()) return say(plan.error), 2;
    int status = applyValues(engine, [&] { return engine.apply(plan.values); });
    if (status == 0 && o.save)
        status = applyValues(engine, [&] { return engine.runAction(config::Action::SaveToFlash); });
    printStatus(roles, engine, fixes.wait(5000));
    return status;
}

// A survey's result kept in the user's site list (a site of that name replaced): 0, or 1 with
// the reason said when the list cannot be read or written (never written over unread).
int saveSurveySite(const std::string &name, const wgs84::Geodetic &antenna,
                   std::optional<double> accuracy) {
    sites::SiteStore store;
    sites::SiteList list;
    QString why;
    if (!store.load(list, why)) return say(why.toStdString()), 1;
    list.add(sites::surveyInSite(name, antenna, accuracy, sites::todayUtc()), true);
    if (!store.save(list, why)) return say(why.toStdString()), 1;
    say("site '" + name + "' saved");
    return 0;
}

int survey(SettingsEngine &engine, const base::BaseRoles &roles, const SurveyOptions &so,
           SetOptions &set, FixWatcher &fixes) {
    base::SurveyIn in(so.goal);
    QEventLoop loop;
    double lastPrinted = -1;
    auto progressLine = [&](bool final) {
        const base::SurveyStatus s = in.status();
        printJson([&](JsonWriter &w) {
            w.beginObject().key(final ? "result" : "survey").beginObject();
            w.field("seconds", s.seconds).field("positions", static_cast<std::uint64_t>(s.count));
            w.field("progress", in.progress());
            w.field("lat", s.mean.latDeg)
                    .field("lon", s.mean.lonDeg)
                    .field("height", s.mean.height);
            w.key("ecef")
                    .beginArray()
                    .value(s.meanEcef.x)
                    .value(s.meanEcef.y)
                    .value(s.meanEcef.z)
                    .endArray();
            w.field("sigma_east", s.sigmaEast)
                    .field("sigma_north", s.sigmaNorth)
                    .field("sigma_up", s.sigmaUp);
            w.field("accuracy", s.accuracy);
            w.endObject().endObject();
        });
    };
    if (so.byReceiver) {
        // The receiver averages: set it so, then follow its own positions until its time is up
        // and the position it found is read back.
        base::BaseRequest q = set.request;
        q.kind = base::BaseRequest::Kind::Averaging;
        q.averagingMinutes = static_cast<int>(*so.goal.seconds / 60);
        q.averagingInput = so.input;
        const auto before =
                roles.position ? engine.receiverValue(roles.position->key) : std::nullopt;
        const base::BasePlan plan = base::planBase(roles, q, knownOf(engine));
        if (!plan.ok()) return say(plan.error), 2;
        if (const int s = applyValues(engine, [&] { return engine.apply(plan.values); }); s != 0)
            return s;
        fixes.waitForTime(5000);
        const double start = fixes.clock();
        QTimer tick;
        QObject::connect(&tick, &QTimer::timeout, [&] {
            const double t = fixes.clock() - start;
            printJson([&](JsonWriter &w) {
                w.beginObject().key("survey").beginObject().field("by", "receiver");
                w.field("seconds", t).field("remaining", std::max(0.0, *so.goal.seconds - t));
                w.endObject().endObject();
            });
            if (t < *so.goal.seconds) return;
            // Its time is up: the position it found is read back. One that does not change
            // within half a minute was averaged before (the mode was already in force).
            runOperation(engine, [&] { return engine.read({std::string(roles.position->key)}); });
            const auto now = engine.receiverValue(roles.position->key);
            if (now && now != before) loop.quit();
            if (t > *so.goal.seconds + 30) loop.exit(now ? 2 : 1);
        });
        tick.start(1000);
        const int ended = loop.exec();
        if (ended == 1) return say("the receiver reports no base position"), 1;
        if (ended == 2)
            say("the receiver's position did not change: it had averaged it before (its mode was "
                "already in force)");
        const auto p = base::ecefOf(engine.receiverValue(roles.position->key).value_or(""));
        printJson([&](JsonWriter &w) {
            w.beginObject().key("result").beginObject().field("by", "receiver");
            if (p) {
                const auto g = wgs84::toGeodetic(*p);
                w.key("ecef").beginArray().value(p->x).value(p->y).value(p->z).endArray();
                if (g) w.field("lat", g->latDeg).field("lon", g->lonDeg).field("height", g->height);
            }
            w.endObject().endObject();
        });
        printStatus(roles, engine, fixes.last);
        if (const auto g = p ? wgs84::toGeodetic(*p) : std::nullopt; so.saveSite && g)
            return saveSurveySite(*so.saveSite, *g, std::nullopt);
        return 0;
    }
    // The workbench averages the receiver's fixes: a base that reports its set position instead
    // of its own is first told to report its own.
    const base::BaseStatus now = base::baseStatus(roles, knownOf(engine), std::nullopt);
    if (now.isBase() && now.nmeaPosition == base::meaningName(OptionMeaning::BasePosition)) {
        std::string own;
        for (const SettingOption &o : roles.nmeaPosition->options)
            if (o.meaning == OptionMeaning::OwnPosition) own = std::string(o.value);
        say("the receiver is a base reporting its set position: it is told to report its own");
        const std::vector<KeyValue> values{{std::string(roles.nmeaPosition->key), own}};
        if (const int s = applyValues(engine, [&] { return engine.apply(values); }); s != 0)
            return s;
        fixes.last.reset();
    }
    fixes.onFix = [&](const base::OwnFix &f, const Epoch &) {
        in.add(fixes.clock(), f.position);
        const double t = in.status().seconds;
        if (t - lastPrinted >= 1) {
            lastPrinted = t;
            progressLine(false);
        }
        if (in.done()) loop.quit();
    };
    QTimer noFix;
    noFix.setSingleShot(true);
    QObject::connect(&noFix, &QTimer::timeout, [&] {
        if (in.status().count == 0) loop.exit(1);
    });
    noFix.start(60000);
    if (loop.exec() != 0) return say("the receiver gave no position within 60 s"), 1;
    fixes.onFix = nullptr;
    progressLine(true);
    const base::SurveyStatus s = in.status();
    if (so.saveSite)
        if (const int status = saveSurveySite(*so.saveSite, s.mean, s.accuracy)) return status;
    if (!so.set) return 0;
    set.ecef = s.meanEcef;
    set.request.position = s.meanEcef;
    return applyBase(engine, roles, set, fixes);
}

} // namespace

int cmdBase(const CliContext &ctx) {
    const Args &args = ctx.args;
    const auto &pos = args.positionals();
    if (pos.size() != 1 || (pos[0] != "status" && pos[0] != "survey" && pos[0] != "set"))
        return say("base needs one action: status, survey or set"), 2;
    const std::string action = pos[0];
    SetOptions set;
    SurveyOptions so;
    if (action == "set")
        if (const int s = parseSet(args, set, true)) return s;
    if (action == "survey") {
        if (const int s = parseSurvey(args, so)) return s;
        if (const int s = parseSet(args, set, false)) return s;
    }
    EventLoop app;
    Link l = openLink(ctx, args);
    if (!l.connection) return l.usageError ? 2 : 1;
    const auto roles = base::baseRoles(*l.dialect);
    if (!roles)
        return say("the " + std::string(l.dialect->displayName) +
                   " cannot be a base station (its dialect has no base mode)"),
               2;
    l.connection->commands()->setDialect(l.dialect);
    SettingsEngine engine;
    engine.attach(l.connection.get(), l.dialect);
    FixWatcher fixes(*l.connection);
    if (!reportRead(runOperation(engine, [&] { return engine.read(roles->keys()); }))) return 1;
    int status = 0;
    if (action == "status") {
        printStatus(*roles, engine, fixes.wait(10000));
    } else if (action == "set") {
        set.request.position = positionOf(set, fixes);
        if (!set.request.position) return 1;
        status = applyBase(engine, *roles, set, fixes);
    } else {
        status = survey(engine, *roles, so, set, fixes);
    }
    return EventLoop::interruptedStatus() ? EventLoop::interruptedStatus() : status;
}

} // namespace gnss::cli
