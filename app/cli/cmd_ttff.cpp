// gnss-cli ttff: a time-to-first-fix campaign on one live receiver (qualify::TtffCampaign, as the
// window runs it): N restarts of each kind asked, a line per run, the statistics at the end.
#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/event_loop.h"
#include "compare/accuracy.h"
#include "core/json_writer.h"
#include "link/vendor_detector.h"
#include "qualify/ttff_campaign.h"

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
    if (const auto text = args.option("reference")) {
        std::string why;
        const auto p = compare::ReferencePoint::parse(*text, why);
        if (!p) {
            std::fprintf(stderr, "gnss-cli: --reference: %s\n", why.c_str());
            return 2;
        }
        plan.reference = std::pair(p->latDeg, p->lonDeg);
    }
    std::string error;
    const auto spec = sourceFromArgs(args, {Kind::Serial, Kind::Tcp, Kind::Simulator}, error);
    if (!spec) {
        std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
        return 2;
    }
    EventLoop loop;
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
    QObject::connect(&detector, &link::VendorDetector::finished,
                     [&](const link::VendorIdentity &id) {
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
    qualify::TtffCampaign campaign(conn.get(), dialect, plan);
    QString last;
    QObject::connect(&campaign, &qualify::TtffCampaign::progress, [&](const QString &text) {
        // Each new state once (the seconds tick on a terminal only).
        const QString state = text.section(QLatin1Char(','), 0, 0);
        if (state == last) return;
        last = state;
        std::fprintf(stderr, "%s\n", utf8(text).c_str());
    });
    QObject::connect(&campaign, &qualify::TtffCampaign::runFinished,
                     [&](const qualify::TtffRun &r) {
                         if (!json) std::printf("%s\n", runText(r).c_str());
                         std::fflush(stdout);
                     });
    QObject::connect(&campaign, &qualify::TtffCampaign::finished,
                     [](bool) { QCoreApplication::exit(0); });
    campaign.start();
    const int rc = loop.exec();
    if (rc) campaign.cancel();
    std::string out;
    if (json) {
        JsonWriter w(out);
        w.beginObject().field("receiver", dialect->displayName);
        w.field("source", utf8(spec->toString()));
        qualify::writeCampaignJson(w, campaign.runs());
        w.endObject();
        out += '\n';
    } else {
        out = statsText(campaign.runs());
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
    return rc ? rc : 0;
}

} // namespace gnss::cli
