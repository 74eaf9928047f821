// gnss-soak: the 24-hour soak (a benchmark program, not a test: it prints what it measures).
//   gnss-soak [--hours H] [--every MIN] [--warm-up H] [--limit MB]
//       the real main window offscreen, every dock shown, on a 20 Hz receiver with about 60
//       satellites, in simulated time as fast as the GUI thread takes it (soak_gui.cpp);
//   gnss-soak --cli monitor|record [--speed X] [--rate HZ] [--sky sim|soak] [--bin DIR] ...
//       gnss-cli on gnss-sim --tcp at X times real time, or on the soak's own 20 Hz sky served
//       on a TCP port (soak_cli.cpp).
// Prints simulated and real time, RSS, heap, CPU and every list's size at each sample; at the
// end the growth from the end of the warm-up and PASS/FAIL (exit 1) against --limit and the caps.
#include "soak_cli.h"
#include "soak_gui.h"

#include <QApplication>
#include <QCommandLineParser>

#include <cstring>
#include <memory>

namespace {

bool parse(const QStringList &arguments, gnss::soak::SoakOptions &o) {
    auto tr = [](const char *s) { return QCoreApplication::translate("gnss-soak", s); };
    QCommandLineParser p;
    p.setApplicationDescription(tr("Soak: memory, CPU and list sizes over many simulated hours."));
    p.addHelpOption();
    const QCommandLineOption hours("hours", tr("Simulated hours (default 24)."), "H", "24");
    const QCommandLineOption every("every", tr("Simulated minutes between samples (default 60)."),
                                   "MIN", "60");
    const QCommandLineOption warm("warm-up", tr("Simulated hours of warm-up (default 1)."), "H",
                                  "1");
    const QCommandLineOption limit("limit", tr("Allowed growth after the warm-up, MB (default 5)."),
                                   "MB", "5");
    const QCommandLineOption cli(
            "cli", tr("Soak gnss-cli monitor or record instead of the window."), "monitor|record");
    const QCommandLineOption bin("bin", tr("Directory of gnss-cli and gnss-sim."), "DIR");
    const QCommandLineOption speed("speed", tr("gnss-sim's speed for --cli (default 1000)."), "X",
                                   "1000");
    const QCommandLineOption rate("rate",
                                  tr("The simulated NV08C-RTK's PVT rate for --cli: 1, 2, "
                                     "5 or 10 Hz (default 10)."),
                                  "HZ", "10");
    const QCommandLineOption sky(
            "sky",
            tr("For --cli: gnss-sim (sim, the default) or the soak's own 20 Hz, 60-satellite sky "
               "on a TCP port (soak)."),
            "sim|soak", "sim");
    p.addOptions({hours, every, warm, limit, cli, bin, speed, rate, sky});
    if (!p.parse(arguments)) {
        std::fprintf(stderr, "gnss-soak: %s\n", qPrintable(p.errorText()));
        return false;
    }
    if (p.isSet("help")) {
        std::printf("%s", qPrintable(p.helpText()));
        std::exit(0);
    }
    o.hours = p.value(hours).toDouble();
    o.everyMinutes = p.value(every).toDouble();
    o.warmUpHours = p.value(warm).toDouble();
    o.limitMb = p.value(limit).toDouble();
    o.cli = p.value(cli);
    o.bin = p.value(bin);
    o.speed = p.value(speed).toDouble();
    o.rateHz = p.value(rate).toInt();
    o.sky = p.value(sky);
    if (!(o.hours > 0) || !(o.everyMinutes > 0) || o.warmUpHours < 0 ||
        (!o.cli.isEmpty() && o.cli != "monitor" && o.cli != "record") ||
        (o.sky != "sim" && o.sky != "soak")) {
        std::fprintf(stderr, "gnss-soak: %s\n",
                     qPrintable(tr("--hours and --every take positive numbers, --cli monitor "
                                   "or record")));
        return false;
    }
    return true;
}

// The offscreen platform says so for every floating dock: not news in a soak's output.
void quietHandler(QtMsgType type, const QMessageLogContext &, const QString &msg) {
    if (msg.startsWith(QLatin1String("This plugin does not support"))) return;
    std::fprintf(stderr, "%s%s\n", type >= QtWarningMsg ? "warning: " : "", qPrintable(msg));
}

} // namespace

int main(int argc, char **argv) {
    qInstallMessageHandler(quietHandler);
    bool cli = false;
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--cli", 5) == 0) cli = true;
    std::unique_ptr<QCoreApplication> app;
    if (cli) {
        app = std::make_unique<QCoreApplication>(argc, argv);
    } else {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
        app = std::make_unique<QApplication>(argc, argv);
    }
    gnss::soak::SoakOptions o;
    if (!parse(QCoreApplication::arguments(), o)) return 2;
    return cli ? gnss::soak::runCliSoak(o) : gnss::soak::runGuiSoak(o);
}
