// gnss-cli ttff: a time-to-first-fix campaign on one live receiver (qualify::TtffCampaign, as the
// window runs it): N restarts of each kind asked, a line per run, the statistics at the end.
#include "config/settings_engine.h"
#include "config/settings_snapshot.h"

#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/event_loop.h"
#include "cli/site_reference.h"
#include "compare/accuracy.h"
#include "core/json_writer.h"
#include "link/vendor_detector.h"
#include "qualify/limits.h"
#include "qualify/report.h"
#include "qualify/ttff_campaign.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLocale>
#include <QTranslator>

#include <cstdio>

namespace gnss::cli {

namespace {

using Kind = link::SourceSpec::Kind;

std::string runText(const qualify::TtffRun &r) {
    char b[256];
    std::string o;
    std::snprintf(b, sizeof b, "%s %d: %s", std::string(toString(r.start)).c_str(), r.index,
                  std::string(qualify::toString(r.outcome)).c_str());
    o = b;
    if (r.fix3d) {
        std::snprintf(b, sizeof b, ", 3D after %.1f s", *r.fix3d);
        o += b;
    }
    if (r.satellitesAtFix) o += ", " + std::to_string(*r.satellitesAtFix) + " satellites";
    if (r.distanceM) {
        std::snprintf(b, sizeof b, ", %.1f m from the reference", *r.distanceM);
        o += b;
    }
    return o;
}

std::string statsText(const std::vector<qualify::TtffRun> &runs) {
    std::string o =
            "start  runs fixed timeouts lost   mean median    p90    p95    min    max (s)\n";
    char b[256];
    for (const qualify::StartStats &s : qualify::statsOf(runs)) {
        std::snprintf(b, sizeof b, "%-5s %5d %5d %8d %4d", std::string(toString(s.start)).c_str(),
                      s.runs, s.fixed, s.timeouts, s.lost);
        o += b;
        if (s.fixed)
            std::snprintf(b, sizeof b, " %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f\n", s.ttff.mean,
                          s.ttff.median, s.p90, s.ttff.p95, s.ttff.min, s.ttff.max);
        else
            std::snprintf(b, sizeof b, "      -      -      -      -      -      -\n");
        o += b;
    }
    return o;
}

std::string limitsText(const std::vector<qualify::LimitResult> &results) {
    std::string o;
    char b[256];
    for (const qualify::LimitResult &r : results) {
        if (r.value)
            std::snprintf(b, sizeof b, "limit %s: %.1f s, %s\n", r.limit.text().c_str(), *r.value,
                          r.pass ? "pass" : "FAIL");
        else
            std::snprintf(b, sizeof b, "limit %s: no run fixed, FAIL\n", r.limit.text().c_str());
        o += b;
    }
    return o;
}

// The report's language: the window's translations (compiled into gnss-cli) and the language's
// notation for numbers, in force only while a Scope lives (what goes to standard output, and the
// progress, stay English).
class ReportLanguage {
public:
    explicit ReportLanguage(const std::string &lang)
        : locale_(lang == "ru" ? QLocale(QLocale::Russian, QLocale::Russia)
                               : QLocale(QLocale::English, QLocale::UnitedStates)),
          loaded_(lang != "en" && translator_.load(locale_, "gnss-workbench", "_", ":/i18n")) {}

    class Scope {
    public:
        explicit Scope(ReportLanguage &l)
            : l_(l), installed_(l.loaded_ && QCoreApplication::installTranslator(&l.translator_)) {
            QLocale::setDefault(l.locale_);
        }
        ~Scope() {
            if (installed_) QCoreApplication::removeTranslator(&l_.translator_);
            QLocale::setDefault(previous_);
        }
        Scope(const Scope &) = delete;
        Scope &operator=(const Scope &) = delete;

    private:
        ReportLanguage &l_;
        QLocale previous_;
        bool installed_;
    };

private:
    QLocale locale_;
    QTranslator translator_;
    bool loaded_;
};

// The receiver's settings as read back, for the report (a receiver that answers nothing leaves
// them empty; the campaign goes on).
std::vector<std::pair<QString, QString>>
readSettings(link::Connection &conn, const Dialect *dialect, ReportLanguage &language) {
    config::SettingsEngine engine;
    engine.attach(&conn, dialect);
    QEventLoop wait;
    QObject::connect(&engine, &config::SettingsEngine::finished, &wait, &QEventLoop::quit);
    if (engine.read()) wait.exec();
    const ReportLanguage::Scope inLanguage(language); // labels and values in the report's
    return config::settingsSnapshot(engine);
}

bool seconds(const Args &args, const char *name, int &ms) {
    const auto v = args.option(name);
    if (!v) return true;
    bool ok = false;
    const double s = QString::fromStdString(*v).toDouble(&ok);
    if (!ok || s < 0 || s > 86400) {
        std::fprintf(stderr, "gnss-cli: --%s expects seconds 0..86400, got '%s'\n", name,
                     v->c_str());
        return false;
    }
    ms = int(s * 1000);
    return true;
}

} // namespace

int cmdTtff(const CliContext &ctx) {
    const Args &args = ctx.args;
    qualify::TtffCampaign::Plan plan;
    for (const std::string &s : args.options("start")) {
        if (s == "cold")
            plan.starts.push_back(ReceiverAction::ColdStart);
        else if (s == "warm")
            plan.starts.push_back(ReceiverAction::WarmStart);
        else if (s == "hot")
            plan.starts.push_back(ReceiverAction::HotStart);
        else {
            std::fprintf(stderr, "gnss-cli: --start takes cold, warm or hot, not '%s'\n",
                         s.c_str());
            return 2;
        }
    }
    if (plan.starts.empty()) {
        std::fprintf(stderr, "gnss-cli: ttff needs --start cold|warm|hot (repeatable)\n");
        return 2;
    }
    if (const auto n = args.option("runs")) {
        bool ok = false;
        plan.runs = QString::fromStdString(*n).toInt(&ok);
        if (!ok || plan.runs < 1 || plan.runs > 10000) {
            std::fprintf(stderr, "gnss-cli: --runs expects 1..10000, got '%s'\n", n->c_str());
            return 2;
        }
    }
    if (!seconds(args, "timeout", plan.timeoutMs) || !seconds(args, "pause", plan.pauseMs) ||
        !seconds(args, "hold", plan.holdMs))
        return 2;
    std::optional<compare::ReferencePoint> reference;
    if (const int rc = referenceFromArgs(args, reference)) return rc;
    if (reference) plan.reference = std::pair(reference->latDeg, reference->lonDeg);
    std::vector<qualify::Limit> limits;
    for (const std::string &text : args.options("limit")) {
        std::string why;
        const auto l = qualify::Limit::parse(text, why);
        if (!l) {
            std::fprintf(stderr, "gnss-cli: --limit %s\n", why.c_str());
            return 2;
        }
        limits.push_back(*l);
    }
    const auto reportPath = args.option("report");
    if (reportPath && !qualify::reportFormatOf(QString::fromStdString(*reportPath))) {
        std::fprintf(stderr, "gnss-cli: --report %s: a report is .pdf or .html\n",
                     reportPath->c_str());
        return 2;
    }
    // The report's language (the system's by default, as the window's) and lengths.
    const bool russianSystem = QLocale::system().language() == QLocale::Russian;
    const std::string lang = args.option("lang").value_or(russianSystem ? "ru" : "en");
    if (lang != "en" && lang != "ru") {
        std::fprintf(stderr, "gnss-cli: --lang expects en or ru, got '%s'\n", lang.c_str());
        return 2;
    }
    const std::string units = args.option("units").value_or("metric");
    if (units != "metric" && units != "imperial") {
        std::fprintf(stderr, "gnss-cli: --units expects metric or imperial, got '%s'\n",
                     units.c_str());
        return 2;
    }
    std::string error;
    const auto spec = sourceFromArgs(args, {Kind::Serial, Kind::Tcp, Kind::Simulator}, error);
    if (!spec) {
        std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
        return 2;
    }
    // A PDF is painted: a QGuiApplication (offscreen without a display).
    EventLoop loop(reportPath.has_value());
    OpenOptions o;
    QString why;
    bool refused = false;
    auto conn = openConnection(ctx, *spec, o, why, &refused);
    if (!conn) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
        return refused ? 2 : 1;
    }
    reportLinkEvents(*conn, "");
    // Who is on the line (a receiver that names no vendor until asked, too): its restarts.
    link::VendorDetector detector(conn->stream());
    detector.setActive(true);
    const Dialect *dialect = nullptr;
    bool identified = false;
    link::VendorIdentity identity;
    QObject::connect(&detector, &link::VendorDetector::finished,
                     [&](const link::VendorIdentity &id) {
                         identity = id;
                         dialect = ctx.registry.find(utf8(id.dialect));
                         if (dialect) conn->stream()->setDialect(dialect);
                         identified = true;
                         QCoreApplication::exit(0);
                     });
    detector.start();
    if (const int rc = loop.exec()) return rc;
    if (!identified) return 1;
    if (const QString no = qualify::TtffCampaign::refusal(dialect, plan.starts); !no.isEmpty()) {
        std::fprintf(stderr, "gnss-cli: ttff: %s; nothing was sent\n", utf8(no).c_str());
        return 2;
    }
    const bool json = args.flag("json");
    ReportLanguage language(lang);
    qualify::ReportReceiver receiver;
    if (reportPath) {
        conn->commands()->setDialect(dialect);
        receiver.settings = readSettings(*conn, dialect, language);
    }
    const QDateTime started = QDateTime::currentDateTimeUtc();
    // The positions between runs: the accuracy against the reference (or, in the report, their
    // own mean) and the location the report names.
    compare::PositionSet positions;
    qualify::TtffCampaign campaign(conn.get(), dialect, plan);
    QObject::connect(&campaign, &qualify::TtffCampaign::epoch,
                     [&](const Epoch &e) { positions.add(e); });
    QString last;
    QObject::connect(&campaign, &qualify::TtffCampaign::progress, [&](const QString &text) {
        // Each new state once (the seconds tick on a terminal only).
        const QString state = text.section(QLatin1Char(','), 0, 0);
        if (state == last) return;
        last = state;
        std::fprintf(stderr, "%s\n", utf8(text).c_str());
    });
    QElapsedTimer clock;
    clock.start();
    QObject::connect(
            &campaign, &qualify::TtffCampaign::runFinished, [&](const qualify::TtffRun &r) {
                if (!json) std::printf("%s\n", runText(r).c_str());
                std::fflush(stdout);
                // Where the campaign is, on standard error with the progress.
                const int done = int(campaign.runs().size());
                const int total = campaign.totalRuns();
                const double s = double(clock.elapsed()) / 1000.0;
                if (done < total)
                    std::fprintf(stderr, "run %d of %d after %.0f s; about %.1f min left\n", done,
                                 total, s, s / done * (total - done) / 60.0);
            });
    QObject::connect(&campaign, &qualify::TtffCampaign::finished,
                     [](bool) { QCoreApplication::exit(0); });
    campaign.start();
    const int rc = loop.exec();
    if (rc) campaign.cancel();
    const auto verdicts = qualify::checkLimits(limits, campaign.runs());
    bool allPass = true;
    for (const auto &v : verdicts) allPass = allPass && v.pass;
    std::string out;
    if (json) {
        JsonWriter w(out);
        w.beginObject().field("receiver", dialect->displayName);
        w.field("source", utf8(spec->toString()));
        qualify::writeCampaignJson(w, campaign.runs());
        qualify::writeLimitsJson(w, verdicts);
        if (reference) {
            w.key("reference");
            positions.against(*reference).report().writeJson(w, *reference);
        }
        w.endObject();
        out += '\n';
    } else {
        out = statsText(campaign.runs()) + limitsText(verdicts);
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
    std::fflush(stdout);
    if (reportPath) {
        const ReportLanguage::Scope inLanguage(language);
        qualify::ReportInput in;
        // The symbols as the window writes them (context Units).
        in.length =
                units == "imperial"
                        ? qualify::LengthUnit{QCoreApplication::translate("Units", "ft"), 3.28084}
                        : qualify::LengthUnit{QCoreApplication::translate("Units", "m"), 1.0};
        in.started = started;
        in.ended = QDateTime::currentDateTimeUtc();
        in.reference = reference;
        in.starts = plan.starts;
        in.runsPerStart = plan.runs;
        in.timeoutS = plan.timeoutMs / 1000.0;
        in.pauseS = plan.pauseMs / 1000.0;
        in.limits = limits;
        receiver.name = QString::fromUtf8(dialect->displayName.data(),
                                          qsizetype(dialect->displayName.size()));
        receiver.model = identity.model;
        receiver.firmware = identity.firmware;
        receiver.port = spec->kind == Kind::Serial || spec->kind == Kind::Tcp ? spec->place()
                                                                              : spec->displayName();
        receiver.baud = conn->transport() ? conn->transport()->baud() : 0;
        receiver.runs = campaign.runs();
        if (const auto mean = positions.mean()) {
            const compare::Accuracy a = positions.against(reference ? *reference : *mean);
            receiver.accuracy = a.report();
            receiver.horizontalErrors = a.horizontalErrors();
            receiver.verticalErrors = a.verticalErrors();
            // In the language's notation, the height in the report's unit.
            const QLocale here;
            in.location = QStringLiteral("%1°, %2°")
                                  .arg(here.toString(mean->latDeg, 'f', 7),
                                       here.toString(mean->lonDeg, 'f', 7));
            if (mean->height)
                in.location +=
                        QStringLiteral(", %1\u00a0%2")
                                .arg(here.toString(*mean->height * in.length.perMetre, 'f', 1),
                                     in.length.symbol);
        }
        in.receivers.push_back(std::move(receiver));
        QString why;
        const QStringList files =
                qualify::writeReport(in, QString::fromStdString(*reportPath), &why);
        if (files.isEmpty()) {
            std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
            return rc ? rc : 1;
        }
        for (const QString &f : files)
            std::fprintf(stderr, "gnss-cli: wrote %s\n", utf8(f).c_str());
    }
    if (rc) return rc;
    // A limit the receiver did not meet: it failed what it was held to.
    return allPass ? 0 : 1;
}

} // namespace gnss::cli
