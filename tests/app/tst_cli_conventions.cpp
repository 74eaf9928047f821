// The command-line conventions every program keeps (docs/cli.md): --help and --version on each
// program and each gnss-cli command (also `gnss-cli help COMMAND`), --opt=value as well as
// --opt value, unknown options refused, data on standard output and messages on standard error,
// and the exit codes: 0 done, 1 failed, 2 usage error, 128 + signal when interrupted.
#include "cli_run.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

namespace {

using gnss::test::Run;

Run run(const QString &program, const QStringList &args, const QByteArray &input = {},
        const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment()) {
    return gnss::test::runProgram(program, args, input, 60000, env);
}

Run cli(const QStringList &args, const QByteArray &input = {}) {
    return gnss::test::runCli(args, input, 60000);
}

QByteArray why(const Run &r) {
    return "exit " + QByteArray::number(r.exitCode) + "\nstdout: " + r.out + "\nstderr: " + r.err;
}

const QStringList kCommands = {"decode",  "epochs", "stats", "schema", "encode", "ports",  "probe",
                               "monitor", "record", "send",  "config", "rtcm",   "compare"};

// The options `gnss-cli COMMAND --help` lists, with the value each takes ("" for a flag).
QList<QPair<QString, QString>> listedOptions(const QString &command) {
    QList<QPair<QString, QString>> options;
    const QByteArray help = cli({command, "--help"}).out;
    const qsizetype at = help.indexOf("\noptions:\n");
    static const QRegularExpression line(QStringLiteral("^  (?:-h, )?--([a-z-]+)(?: (\\S+))?"));
    for (const QByteArray &l : help.mid(at).split('\n')) {
        const auto m = line.match(QString::fromUtf8(l));
        if (m.hasMatch()) options.append({m.captured(1), m.captured(2)});
    }
    return options;
}

const QByteArray kNmea = "$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,"
                         "0014.4,M,000.6,0100*46\r\n";

// Three epochs of kNmea in `dir`/`name`; its path, or empty when it could not be written.
QString writePlainLog(const QTemporaryDir &dir, const char *name) {
    const QString path = dir.filePath(QString::fromLatin1(name));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(kNmea.repeated(3)) < 0) return {};
    return path;
}

} // namespace

class TstCliConventions : public QObject {
    Q_OBJECT
private slots:
    void everyCommandHasHelpAndVersion_data() {
        QTest::addColumn<QString>("command");
        for (const QString &c : kCommands) QTest::newRow(qPrintable(c)) << c;
    }
    void everyCommandHasHelpAndVersion() {
        QFETCH(QString, command);
        const Run help = cli({command, "--help"});
        QVERIFY2(help.exitCode == 0 && help.err.isEmpty(), why(help));
        QVERIFY2(help.out.startsWith("usage: gnss-cli " + command.toUtf8()), why(help));
        QVERIFY2(help.out.contains("Exit status:"), why(help));
        QVERIFY2(help.out.contains("-h, --help") && help.out.contains("--version"), why(help));
        // The same text however it is asked for, and wherever --help is on the line.
        QCOMPARE(cli({"help", command}).out, help.out);
        QCOMPARE(cli({command, "-h"}).out, help.out);
        QCOMPARE(cli({command, "--no-such-option", "--help"}).out, help.out);
        for (const QString &args : {QString("--version"), QString("--help")}) {
            const Run r = cli({command, args});
            QCOMPARE(r.exitCode, 0);
        }
        const Run version = cli({command, "--version"});
        QCOMPARE(version.out, QByteArray("gnss-cli " GNSS_VERSION "\n"));
        QVERIFY(version.err.isEmpty());
    }

    void everyListedOptionIsAcceptedBothWays_data() { everyCommandHasHelpAndVersion_data(); }
    void everyListedOptionIsAcceptedBothWays() {
        // Parsed, not run: --help after the option shows the option was taken as given.
        QFETCH(QString, command);
        const auto options = listedOptions(command);
        QVERIFY(options.size() >= 2); // --help and --version at least
        for (const auto &[name, value] : options) {
            if (name == "help" || name == "version") continue;
            const QString opt = "--" + name;
            if (value.isEmpty()) {
                QCOMPARE(cli({command, opt, "--help"}).exitCode, 0);
                const Run withValue = cli({command, opt + "=1"});
                QVERIFY2(withValue.exitCode == 2 && withValue.err.contains("takes no value"),
                         why(withValue));
            } else {
                QCOMPARE(cli({command, opt, "x", "--help"}).exitCode, 0);
                QCOMPARE(cli({command, opt + "=x", "--help"}).exitCode, 0);
                // A separate value never starts with "--": that is a value left out.
                const Run missing = cli({command, opt, "--version"});
                QCOMPARE(missing.exitCode, 0); // --version still wins...
                const Run alone = cli({command, opt});
                QVERIFY2(alone.exitCode == 2 && alone.err.contains("needs a value") &&
                                 alone.out.isEmpty(),
                         why(alone)); // ...and alone it is a usage error
            }
        }
    }

    void unknownOptionsAndCommandsAreUsageErrors_data() { everyCommandHasHelpAndVersion_data(); }
    void unknownOptionsAndCommandsAreUsageErrors() {
        QFETCH(QString, command);
        for (const char *bad : {"--no-such-option", "--no-such-option=1", "-x"}) {
            const Run r = cli({command, bad});
            QVERIFY2(r.exitCode == 2, why(r));
            QVERIFY2(r.out.isEmpty(), why(r));
            QVERIFY2(r.err.contains("unknown option"), why(r));
            QVERIFY2(r.err.contains("gnss-cli help " + command.toUtf8()), why(r));
        }
    }

    void programLevelHelpVersionAndErrors() {
        const Run help = cli({"--help"});
        QVERIFY2(help.exitCode == 0 && help.err.isEmpty(), why(help));
        for (const QString &c : kCommands)
            QVERIFY2(help.out.contains("\n  " + c.toUtf8() + " ") ||
                             help.out.contains("\n  " + c.toUtf8() + "\n"),
                     qPrintable(c));
        QCOMPARE(cli({"-h"}).out, help.out);
        QCOMPARE(cli({"help"}).out, help.out);
        const Run version = cli({"--version"});
        QVERIFY2(version.exitCode == 0 && version.out == "gnss-cli " GNSS_VERSION "\n",
                 why(version));

        const Run nothing = cli({});
        QVERIFY2(nothing.exitCode == 2 && nothing.out.isEmpty() &&
                         nothing.err.contains("usage: gnss-cli"),
                 why(nothing));
        for (const QStringList &args :
             {QStringList{"frobnicate"}, QStringList{"--frobnicate"},
              QStringList{"help", "frobnicate"}, QStringList{"help", "decode", "epochs"}}) {
            const Run r = cli(args);
            QVERIFY2(r.exitCode == 2 && r.out.isEmpty() && !r.err.isEmpty(), why(r));
        }
    }

    void optionValuesWithEqualsMeanTheSame() {
        QTemporaryDir dir;
        const QString log = writePlainLog(dir, "a.nmea");
        QVERIFY(!log.isEmpty());
        QCOMPARE(cli({"decode", "--dialect=nmea", log}).out,
                 cli({"decode", "--dialect", "nmea", log}).out);
        QCOMPARE(cli({"encode", "nemerix", "--prefix=PXYZW", "--query", "rate.GGA"}).out,
                 QByteArray("$PXYZW603*69\n"));
        const Run stats = cli({"stats", "--threads=1", "--json", log});
        QVERIFY2(stats.exitCode == 0 && stats.out.contains("\"threads\":1"), why(stats));
        const Run replay = cli({"monitor", "--replay=" + log, "--fast", "--duration=30"});
        QVERIFY2(replay.exitCode == 0, why(replay));
        QCOMPARE(replay.out, cli({"decode", log}).out);
        // "--" ends the options: a file whose name starts with "--" is read, not refused.
        QVERIFY(QFile::copy(log, dir.filePath("--odd.nmea")));
        QProcess p;
        p.setWorkingDirectory(dir.path());
        p.start(QStringLiteral(GNSS_CLI_PATH), {"decode", "--", "--odd.nmea"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(p.readAllStandardOutput().count('\n'), 3);
        p.start(QStringLiteral(GNSS_CLI_PATH), {"decode", "--odd.nmea"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 2);
    }

    void dataOnStandardOutputMessagesOnStandardError() {
        const Run ok = cli({"decode", "-"}, kNmea);
        QVERIFY2(ok.exitCode == 0 && ok.err.isEmpty() && ok.out.startsWith("{"), why(ok));
        const Run unreadable = cli({"decode", "/nonexistent/log.nmea"});
        QVERIFY2(unreadable.exitCode == 1 && unreadable.out.isEmpty() &&
                         unreadable.err.contains("/nonexistent/log.nmea"),
                 why(unreadable));
    }

    void exitCodesOfEachKindOfFailure() {
        // 2: the command line is wrong, nothing is opened.
        for (const QStringList &args :
             {QStringList{"decode", "--dialect", "garmin", "-"}, QStringList{"decode", "a", "b"},
              QStringList{"schema"}, QStringList{"schema", "garmin"}, QStringList{"encode", "nvs"},
              QStringList{"probe"}, QStringList{"monitor", "--port", "a", "--tcp", "b"},
              QStringList{"record"},
              QStringList{"send", "--port", "/dev/null-no-such-port", "PN$VG"},
              QStringList{"config", "get"}, QStringList{"config", "--sim", "nvs"},
              QStringList{"config", "--sim", "nvs", "--baud", "5", "get"},
              QStringList{"config", "--sim", "nvs", "--dialect", "garmin", "get"},
              QStringList{"encode", "geostar", "nav.ELEV=99"}, QStringList{"rtcm", "a", "b"}}) {
            const Run r = cli(args);
            QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ') + "\n" + why(r)));
            QVERIFY2(!r.err.isEmpty(), qPrintable(args.join(' ')));
        }
        // 1: could not be done.
        for (const QStringList &args :
             {QStringList{"decode", "/nonexistent"}, QStringList{"rtcm", "/nonexistent"},
              QStringList{"monitor", "--port", "/dev/ttyGNSSWorkbenchNoSuchPort"},
              QStringList{"probe", "--port", "/dev/ttyGNSSWorkbenchNoSuchPort"}}) {
            const Run r = cli(args);
            QVERIFY2(r.exitCode == 1, qPrintable(args.join(' ') + "\n" + why(r)));
        }
    }

    void interruptedMonitorAndRecordExitWith128PlusTheSignal_data() {
        QTest::addColumn<QString>("command");
        QTest::addColumn<int>("signal");
        QTest::addColumn<int>("code");
        QTest::newRow("monitor SIGINT") << "monitor" << SIGINT << 130;
        QTest::newRow("monitor SIGTERM") << "monitor" << SIGTERM << 143;
        QTest::newRow("record SIGINT") << "record" << SIGINT << 130;
    }
    void interruptedMonitorAndRecordExitWith128PlusTheSignal() {
        QFETCH(QString, command);
        QFETCH(int, signal);
        QFETCH(int, code);
        // A TCP source that says nothing: the command waits until it is interrupted.
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        QTemporaryDir dir;
        QStringList args{command, "--tcp", QString("127.0.0.1:%1").arg(server.serverPort())};
        if (command == "record") args << "--out" << dir.filePath("r.nmea");
        QProcess p;
        p.start(QStringLiteral(GNSS_CLI_PATH), args);
        QVERIFY(p.waitForStarted());
        QVERIFY(server.waitForNewConnection(10000));
        QTest::qWait(300); // its signal handlers are in place once it is connected
        ::kill(static_cast<pid_t>(p.processId()), signal);
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit); // ended itself, cleanly
        QCOMPARE(p.exitCode(), code);
        if (command == "record") {
            QVERIFY(QFile::exists(dir.filePath("r.nmea")));
            QVERIFY(QFile::exists(dir.filePath("r.nmea.idx")));
        }
    }

    void gnssSimConventions() {
#ifndef GNSS_SIM_PATH
        QSKIP("gnss-sim is not built");
#else
        const QString sim = QStringLiteral(GNSS_SIM_PATH);
        const Run help = run(sim, {"--help"});
        QVERIFY2(help.exitCode == 0 && help.out.startsWith("usage: gnss-sim") &&
                         help.out.contains("Exit status:") && help.err.isEmpty(),
                 why(help));
        QCOMPARE(run(sim, {"--no-such-option", "-h"}).out, help.out);
        const Run version = run(sim, {"--version"});
        QVERIFY2(version.exitCode == 0 && version.out == "gnss-sim " GNSS_VERSION "\n",
                 why(version));
        for (const QStringList &args :
             {QStringList{}, QStringList{"--dialect"}, QStringList{"--dialect", "--pty"},
              QStringList{"--dialect=garmin"}, QStringList{"--dialect=nmea", "--pty=1"},
              QStringList{"--dialect=nmea", "--bogus"}, QStringList{"--dialect=nmea", "extra"},
              QStringList{"--dialect=nmea", "--speed=0"}}) {
            const Run r = run(sim, args);
            QVERIFY2(r.exitCode == 2 && r.out.isEmpty() && r.err.contains("gnss-sim --help"),
                     qPrintable(args.join(' ') + "\n" + why(r)));
        }
        // --opt=value runs; standard input closing ends it with 0.
        const Run stdoutRun = run(sim, {"--dialect=nmea", "--stdout", "--speed=20"});
        QVERIFY2(stdoutRun.exitCode == 0, why(stdoutRun));
        // A signal ends it with 128 + the signal, as gnss-cli.
        QProcess p;
        p.start(sim, {"--dialect", "nmea", "--pty"});
        QVERIFY(p.waitForReadyRead(5000));
        ::kill(static_cast<pid_t>(p.processId()), SIGTERM);
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 143);
#endif
    }

    // Messages say the cause: the busy port by number, every fault there is, how many outputs
    // were given, the same dialect name as summary's for a log without vendor sentences.
    void messagesSayTheCause() {
#ifdef GNSS_SIM_PATH
        const QString sim = QStringLiteral(GNSS_SIM_PATH);
        QTcpServer busy;
        QVERIFY(busy.listen(QHostAddress::LocalHost));
        const QString port = QString::number(busy.serverPort());
        const Run taken = run(sim, {"--dialect", "nmea", "--tcp", port});
        QVERIFY2(taken.exitCode != 0 && taken.err.contains("127.0.0.1:" + port.toUtf8()),
                 why(taken));
        const Run fault = run(sim, {"--dialect", "nmea", "--faults", "nosuch=1"});
        QVERIFY2(fault.exitCode == 2 && fault.err.contains("hangupon"), why(fault));
#endif
        QTemporaryDir dir;
        const QString log = writePlainLog(dir, "plain.nmea");
        QVERIFY(!log.isEmpty());
        const Run two = cli({"play", log, "--pty", "--tcp", "17002"});
        QVERIFY2(two.exitCode == 2 && two.err.contains("not 2 of them"), why(two));
        const Run stats = cli({"stats", "--json", log});
        QVERIFY2(stats.out.contains("\"dialect\":\"nmea\""), why(stats));
        QVERIFY2(cli({"summary", "--json", log}).out.contains("\"dialect\":\"nmea\""), why(stats));
    }

    void gnssWorkbenchHelpAndVersionNeedNoDisplay() {
#ifndef GNSS_WORKBENCH_PATH
        QSKIP("the GUI is not built");
#else
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *v : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) env.remove(v);
        // English text is looked for: not the preferences of whoever runs the tests.
        QTemporaryDir home;
        QVERIFY(home.isValid());
        env.insert("XDG_CONFIG_HOME", home.path());
        for (const char *v : {"LANG", "LC_ALL", "LC_MESSAGES"}) env.insert(v, "C.UTF-8");
        env.remove("LANGUAGE");
        const QString gui = QStringLiteral(GNSS_WORKBENCH_PATH);
        const Run version = run(gui, {"--version"}, {}, env);
        QVERIFY2(version.exitCode == 0 && version.out == "gnss-workbench " GNSS_VERSION "\n",
                 why(version));
        const Run help = run(gui, {"--help"}, {}, env);
        QVERIFY2(help.exitCode == 0 && help.out.contains("--port") &&
                         help.out.contains("Exit status:"),
                 why(help));
        env.insert("QT_QPA_PLATFORM", "offscreen");
        for (const QStringList &args :
             {QStringList{"--no-such-option"}, QStringList{"a.nmea", "b.nmea"},
              QStringList{"--baud", "x"}, QStringList{"--sim", "nvs", "a.nmea"}}) {
            const Run r = run(gui, args, {}, env);
            QVERIFY2(r.exitCode == 2 && r.out.isEmpty(), qPrintable(args.join(' ') + why(r)));
        }
        // A log that is not there is a failure to open it, not a wrong command line.
        const Run missing = run(gui, {"/nonexistent/log.nmea"}, {}, env);
        QVERIFY2(missing.exitCode == 1 &&
                         missing.err.contains("No such log: /nonexistent/log.nmea"),
                 why(missing));
#endif
    }

    // The language of the preferences is the language the workbench starts in: Russian on an
    // English system when chosen, English on a Russian system when chosen, the system's by
    // default. (Its message about an unknown dock shows which.)
    void gnssWorkbenchStartsInThePreferredLanguage_data() {
        QTest::addColumn<QString>("preference");
        QTest::addColumn<QString>("systemLanguage");
        QTest::addColumn<bool>("russian");
        QTest::newRow("ru on an English system") << "ru"
                                                 << "en_US.UTF-8" << true;
        QTest::newRow("en on a Russian system") << "en"
                                                << "ru_RU.UTF-8" << false;
        QTest::newRow("system, Russian") << "system"
                                         << "ru_RU.UTF-8" << true;
        QTest::newRow("system, English") << "system"
                                         << "en_US.UTF-8" << false;
    }
    void gnssWorkbenchStartsInThePreferredLanguage() {
#ifndef GNSS_WORKBENCH_PATH
        QSKIP("the GUI is not built");
#else
        QFETCH(QString, preference);
        QFETCH(QString, systemLanguage);
        QFETCH(bool, russian);
        QTemporaryDir home;
        QVERIFY(home.isValid());
        {
            QDir().mkpath(home.filePath("GNSS Workbench"));
            QFile conf(home.filePath("GNSS Workbench/GNSS Workbench.conf"));
            QVERIFY(conf.open(QIODevice::WriteOnly));
            conf.write("[ui]\nlanguage=" + preference.toUtf8() + "\n");
        }
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.insert("XDG_CONFIG_HOME", home.path());
        for (const char *v : {"LANG", "LC_ALL", "LC_MESSAGES", "LANGUAGE"})
            env.insert(v, systemLanguage);
        env.remove("LANGUAGE");
        const Run r = run(QStringLiteral(GNSS_WORKBENCH_PATH), {"--show-dock", "nosuch"}, {}, env);
        QCOMPARE(r.exitCode, 2);
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(err.contains(russian ? "Неизвестная панель" : "Unknown dock"), qPrintable(err));
#endif
    }
};

QTEST_GUILESS_MAIN(TstCliConventions)
#include "tst_cli_conventions.moc"
