// The commands README.md and docs/cli.md show, run, so the documents cannot drift from the
// programs. Every command line in their code blocks, and every `gnss-...` span with arguments in
// their text, is found and must be in the table below, which says what becomes of it:
//   Run       it is run as written by sh, in a folder holding the logs it names (drive.nmea,
//             yesterday.nmea: a simulated NV08C-RTK's), with the built programs first on PATH;
//             its exit status is checked, and the output the document shows under a `$ ` line
//             must come out (digits and "..." in it stand for any);
//   Synopsis  a usage line: its command exists and every option it names is in that command's
//             --help;
//   Hardware  it needs a receiver, a network or a display this suite has not (the reason is
//             given); its options are checked as a synopsis's.
// A line the table does not know, or a table row no document shows, fails the suite.
#include "cli_run.h"
#include "local_port.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

using gnss::test::Run;

struct DocCommand {
    QString file;        // README.md, docs/cli.md
    QString text;        // one line: continuations joined, the prompt and comments taken off
    QStringList shown;   // the output the document shows after a `$ ` line
    bool inText = false; // a span in the text: a synopsis unless the table says otherwise
};

enum class Kind { Run, Synopsis, Hardware };

struct Treatment {
    Kind kind;
    int status = 0;      // Run: the exit status
    QString note;        // Hardware: why it is not run; Run: a wrapper ("timeout 2")
    QStringList replace; // Run: pairs of text to replace before running (a free port ...)
};

Treatment run(int status = 0, const QString &wrapper = {}, const QStringList &replace = {}) {
    return {Kind::Run, status, wrapper, replace};
}
Treatment synopsis() {
    return {Kind::Synopsis};
}
Treatment hardware(const QString &why) {
    return {Kind::Hardware, 0, why};
}

const QStringList kPrograms = {"gnss-cli", "gnss-sim", "gnss-workbench", "./quickstart.sh",
                               "str2str",  "printf",   "NTRIP_PW="};

bool startsWithProgram(const QString &line) {
    for (const QString &p : kPrograms)
        if (line.startsWith(p)) return true;
    return false;
}

QString simplified(QString s) {
    return s.replace(QRegularExpression(QStringLiteral("\\\\\\s*$|\\\\\n")), " ").simplified();
}

// The command lines of a Markdown document.
QList<DocCommand> commandsOf(const QString &name, const QString &text) {
    QList<DocCommand> out;
    const QStringList lines = text.split('\n');
    static const QRegularExpression comment(QStringLiteral("\\s+#\\s.*$"));
    static const QRegularExpression inlineSpan(
            QStringLiteral("`((?:gnss-cli|gnss-sim|gnss-workbench|\\./quickstart\\.sh) [^`]*)`"));
    bool fenced = false, promptBlock = false;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString &line = lines[i];
        if (line.startsWith("```")) {
            fenced = !fenced;
            promptBlock = false;
            if (fenced)
                for (qsizetype j = i + 1; j < lines.size() && !lines[j].startsWith("```"); ++j)
                    promptBlock = promptBlock || lines[j].startsWith("$ ");
            continue;
        }
        const bool indented = !fenced && line.startsWith("    ");
        if (!fenced && !indented) {
            // A span that only names a command ("gnss-cli monitor") is a reference, not a line.
            for (auto m = inlineSpan.globalMatch(line); m.hasNext();)
                if (const QString t = m.next().captured(1).simplified();
                    t.count(' ') > 1 || t.contains(" -"))
                    out.append({name, t, {}, true});
            continue;
        }
        QString t = line.trimmed();
        if (promptBlock) {
            if (!t.startsWith("$ ")) continue;
            t = t.mid(2);
        } else if (!startsWithProgram(t)) {
            continue;
        }
        // Continuations: a trailing backslash, or (a usage line) an indented "[" that follows.
        while (i + 1 < lines.size() &&
               (t.endsWith('\\') || lines[i + 1].trimmed().startsWith('[')) &&
               !lines[i + 1].startsWith("```"))
            t = t.chopped(t.endsWith('\\') ? 1 : 0) + ' ' + lines[++i].trimmed();
        if (indented) t.remove(comment);
        DocCommand c{name, simplified(t), {}, false};
        if (promptBlock)
            for (qsizetype j = i + 1;
                 j < lines.size() && !lines[j].startsWith("```") && !lines[j].startsWith("$ "); ++j)
                c.shown << lines[j];
        out.append(c);
    }
    return out;
}

// The two logs docs/cli.md compares (made again before the suite runs, so its rows stand alone).
const char *const kCompareA =
        "gnss-sim --dialect nmea --stdout --speed 1000 --duration 600 > a.nmea";
const char *const kCompareB = "gnss-sim --dialect nmea --stdout --speed 1000 --duration 600 "
                              "--offset 0.3,-0.2,0.5 --cn0-offset GPS:-3 > b.nmea";

// What each documented command is (see the top of the file). The key is the command as the
// document writes it, on one line.
QHash<QString, Treatment> table() {
    const QString free = "%FREE%"; // a TCP port nobody uses
    return {
            // README.md
            {"./quickstart.sh run", hardware("builds and starts the window: the CI runs the "
                                             "test command, and tst_main_window the window")},
            {"./quickstart.sh test", hardware("is the CI itself (.ci/run)")},
            {"./quickstart.sh run --port /dev/ttyUSB0", hardware("a receiver on a serial port")},
            {"gnss-workbench --sim nvs|geostar|nemerix|nmea", synopsis()},
            {"gnss-workbench --port /dev/ttyUSB0 [--baud 115200]",
             hardware("a receiver on a serial port")},
            {"gnss-workbench --tcp 192.168.1.20:4001", hardware("a serial server on a network")},
            {"gnss-workbench --gpsd gpsd://localhost/dev/ttyACM0",
             hardware("gpsd holding a receiver")},
            {"gnss-workbench yesterday.nmea [--at 10:42:00]", synopsis()},
            {"gnss-workbench --replay yesterday.nmea",
             run(0, "QT_QPA_PLATFORM=offscreen",
                 {"yesterday.nmea", "yesterday.nmea --quit-after 1"})},
            {"gnss-workbench --sim nvs --sim geostar",
             run(0, "QT_QPA_PLATFORM=offscreen",
                 {"--sim geostar", "--sim geostar --quit-after 2"})},
            {"gnss-cli summary --json", run(0, {}, {"--json", "--json yesterday.nmea"})},
            // Run by tests/qualify/tst_ttff_cli (limitsAndTheReport) on a simulator of its own.
            {"gnss-cli ttff --report r.pdf", synopsis()},
            {"gnss-sim --ttff cold=60:9,hot=12 --speed 20", synopsis()},
            {"gnss-cli serve --sim nvs --raw 0", run(0, {}, {"--raw 0", "--raw 0 --duration 2"})},
            {"gnss-sim --dialect D --pty", synopsis()},
            {"gnss-sim --faults badcs=0.05,binary=0.2,hangup=60",
             run(0, {},
                 {"--faults", "--dialect nmea --stdout --speed 100 --faults", "hangup=60",
                  "hangup=1"})},
            // It ends when its standard input closes, as here.
            {"gnss-sim --rtcm-base --tcp 5000", run(0, "timeout 10", {"5000", free})},
            // docs/cli.md
            {"gnss-cli decode --help", run()},
            {"gnss-cli help decode", run()},
            {"gnss-cli monitor --port --help", run()},
            {"gnss-cli --list-dialects", run()},
            {"gnss-sim --list-dialects", run()},
            {"gnss-cli schema D", synopsis()},
            {"gnss-workbench --port /dev/pts/7", hardware("the pseudo-terminal play opened")},
            {"gnss-workbench LOG --at T", synopsis()},
            {"gnss-cli decode [--dialect D] [--lenient] [FILE|-]", synopsis()},
            {"printf '$GPGPQ,PNVGTST*21\\r\\n' | gnss-cli decode", run()},
            {"gnss-cli epochs [--dialect D] [--lenient] [FILE|-]", synopsis()},
            {"gnss-cli stats [--dialect D] [--lenient] [--json] [--threads N] [FILE|-]",
             synopsis()},
            {"gnss-cli export --format gpx|kml|csv|nmea [--from T] [--to T] FILE -o OUT",
             synopsis()},
            {"gnss-cli summary [--json] [--from T] [--to T] [--reference LAT,LON[,HEIGHT] | "
             "--reference-site NAME] FILE",
             synopsis()},
            {"gnss-cli play FILE --pty|--tcp PORT|--port P [--baud B] [--speed X] [--loop] "
             "[--from T] [--to T]",
             synopsis()},
            // The same log every time (the summary below shows its figures).
            {"gnss-sim --dialect nvs --internal-base --stdout --speed 1000 --duration 3600 > "
             "drive.nmea",
             run(0, {}, {"> drive.nmea", "> again.nmea && cmp again.nmea drive.nmea"})},
            {"gnss-cli summary drive.nmea", run()},
            {"gnss-sim --dialect nvs --stdout --speed 1000 --duration 120 --noise 0 --offset "
             "0.3,-0.2,0.5 > off.nmea",
             run()},
            {"gnss-cli summary --reference 55.7512,37.6184,166.6 off.nmea", run()},
            {"gnss-cli export --format gpx --from 10:15:00 --to 10:20:00 drive.nmea -o part.gpx",
             run()},
            // A minute of the same receiver, and a reader of the pseudo-terminal until play ends.
            {"gnss-cli play drive.nmea --pty --speed 10",
             run(0, {},
                 {"drive.nmea --pty --speed 10",
                  "minute.nmea --pty --speed 1000 | { read dev; echo $dev; "
                  "timeout 20 cat $dev > /dev/null; }; exit ${PIPESTATUS[0]}"})},
            {"gnss-cli ttff --port P|--tcp HOST:PORT|--sim D --start cold|warm|hot [--start ...] "
             "[--runs N] [--timeout S] [--pause S] [--hold S] [--reference LAT,LON[,HEIGHT] | "
             "--reference-site NAME] [--limit START:STAT<=S ...] [--report FILE.pdf|FILE.html] "
             "[--lang en|ru] [--units metric|imperial] [--json]",
             synopsis()},
            // The site list (tests/sites/tst_sites_cli runs them in a data folder of its own).
            {"gnss-cli sites list [--json]", synopsis()},
            {"gnss-cli sites add NAME --llh LAT,LON[,HEIGHT]|--ecef X,Y,Z [--antenna-height H] "
             "[--accuracy M] [--date D] [--method TEXT] [--note TEXT] [--replace]",
             synopsis()},
            {"gnss-cli sites remove NAME", synopsis()},
            // The base station (tests/base/tst_base_cli runs them against gnss-sim).
            {"gnss-cli base --port P [--baud B] | --tcp HOST:PORT | --sim D status", synopsis()},
            {"gnss-cli base ... survey --minutes M | --sigma METRES [--by-receiver [--input V]] "
             "[--save-site NAME] [--set ...]",
             synopsis()},
            {"gnss-cli base ... set --ecef X,Y,Z | --llh LAT,LON,HEIGHT [--msl] | --site NAME "
             "[--antenna-height H] [--station N] [--rtcm-port N [--rtcm-baud B]] "
             "[--rtcm-interval S] [--save]",
             synopsis()},
            {"gnss-sim --dialect nvs --pty --link /tmp/base --com2 --com2-link /tmp/base-com2 "
             "--speed 10 < /dev/null &",
             hardware("a simulator left running in the background: tst_base_cli")},
            {"gnss-cli base --port /tmp/base survey --minutes 1 --save-site \"Roof\" --set "
             "--rtcm-port 2 --save",
             hardware("the simulator started above: tst_base_cli")},
            {"gnss-cli serve --port /tmp/base-com2 --baud 115200 --ntrip 2101/NVSB &",
             hardware("the simulator started above: tst_base_cli")},
            {"gnss-sim --dialect nvs --pty --link /tmp/rover --speed 10 --seed 2 < /dev/null &",
             hardware("a simulator left running in the background: tst_base_cli")},
            {"gnss-cli ntrip --caster 127.0.0.1:2101 --mount NVSB --port /tmp/rover --duration 20",
             hardware("the caster and rover started above: tst_base_cli")},
            {"gnss-cli sites export FILE.csv|FILE.json", synopsis()},
            {"gnss-cli sites import FILE.csv|FILE.json [--replace]", synopsis()},
            // Run by tests/qualify/tst_ttff_cli on a pseudo-terminal of its own.
            {"gnss-sim --dialect nemerix --pty --link /tmp/vt002 --speed 20 --ttff cold=40:4 < "
             "/dev/null &",
             hardware("a simulator left running in the background")},
            {"gnss-cli ttff --port /tmp/vt002 --start cold --runs 5 --pause 0.5 --limit "
             "cold:mean<=60 --report vt002.pdf",
             hardware("the simulator started above")},
            {"gnss-cli rtcm [FILE|-]", synopsis()},
            {"printf '\\xD3\\x00\\x13\\x3E\\xD7\\xD3\\x02\\x02\\x98\\x0E\\xDE\\xEF\\x34\\xB4\\xBD"
             "\\x62\\xAC\\x09\\x41\\x98\\x6F\\x33\\x36\\x0B\\x98' | gnss-cli rtcm",
             run(0, {}, {"gnss-cli rtcm", "gnss-cli rtcm 2>&1"})},
            {"gnss-cli ntrip --caster HOST:PORT --mount M | --sourcetable | --nearest [--user U] "
             "[--password-env VAR] [--ntrip-version 1|2] [--gga auto|LAT,LON,H] [--out FILE] "
             "[--duration S] [--quiet] [--port P [--baud B] | --tcp HOST:PORT | --sim D]",
             synopsis()},
            {"NTRIP_PW=... gnss-cli ntrip --caster caster.example.org:2101 --mount MOSC00RUS0 "
             "--user me --password-env NTRIP_PW --out mosc.rtcm --duration 60",
             hardware("a caster on the Internet")},
            {"str2str -in tcpcli://127.0.0.1:5000 -out 'ntripc://user:pass@:2101/SIM:SIM;RTCM "
             "3.2;1005(1),1074(1),1084(1);1;GPS+GLO;LOCAL;XXX;55.75;37.62;0;0;gnss-sim;none;B;N;"
             "9600;'",
             hardware("RTKLIB's str2str: tst_ntrip_str2str runs it as this caster")},
            {"NTRIP_PW=pass gnss-cli ntrip --caster 127.0.0.1:2101 --mount SIM --user user "
             "--password-env NTRIP_PW --ntrip-version 1",
             hardware("the str2str caster above: tst_ntrip_str2str")},
            {"gnss-cli serve --port P [--baud B] | --tcp HOST:PORT | --sim D | --replay FILE "
             "[--loop] [--ntrip [ADDR:]PORT/MOUNT [--user U --password-env VAR]] [--raw "
             "[ADDR:]PORT] [--duration S]",
             synopsis()},
            {"NTRIP_PW=... gnss-cli serve --tcp 127.0.0.1:5000 --ntrip 2101/BASE --user me "
             "--password-env NTRIP_PW",
             hardware("gnss-sim --rtcm-base on port 5000: tst_serve_cli serves it so")},
            {"str2str -in ntrip://me:pass@127.0.0.1:2101/BASE -out file://base.rtcm",
             hardware("the caster above: tst_serve_cli runs str2str so")},
            {"gnss-cli serve --sim nmea --raw 0 --duration 2", run()},
            {"gnss-cli serve --replay base.rtcm --loop --ntrip 0.0.0.0:2101/BASE",
             hardware("a caster on every interface until Ctrl-C")},
            {"gnss-cli compare SOURCE SOURCE [SOURCE...] [--duration S] [--json] [--dialect D] "
             "[--lenient]",
             synopsis()},
            {kCompareA, run()},
            {kCompareB, run()},
            // Its summary in words is on standard error.
            {"gnss-cli compare a.nmea b.nmea", run(0, {}, {"b.nmea", "b.nmea 2>&1"})},
            {"gnss-cli schema DIALECT", synopsis()},
            {"gnss-cli encode DIALECT KEY=VALUE...", synopsis()},
            {"gnss-cli encode DIALECT --query KEY...", synopsis()},
            {"gnss-cli ports", run()},
            {"gnss-cli probe --port P [--baud B] | --tcp H:P | --gpsd HOST[:PORT][/DEVICE]",
             synopsis()},
            {"gnss-cli monitor --port P|--tcp H:P|--gpsd G|--replay FILE [--baud B] [--epochs] "
             "[--duration S] [--dialect D] [--lenient] [--speed X] [--fast]",
             synopsis()},
            {"gnss-cli record --port P|--tcp H:P|--gpsd G --out FILE [--duration S] [--baud B]",
             synopsis()},
            {"gnss-cli send --port P|--tcp H:P [--baud B] [--dialect D] [--timeout S] "
             "[--fix-checksum] SENTENCE...",
             synopsis()},
            {"gnss-cli monitor --gpsd localhost --epochs", hardware("gpsd holding a receiver")},
            {"gnss-cli config (--port P [--baud B] | --sim DIALECT) [--dialect D] get [KEY...]",
             synopsis()},
            {"gnss-cli config ... set KEY=VALUE...", synopsis()},
            {"gnss-cli config ... export FILE", synopsis()},
            {"gnss-cli config ... apply FILE", synopsis()},
            {"gnss-cli config ... diff FILE", synopsis()},
            {"gnss-cli config ... action save|defaults|cold|warm|hot", synopsis()},
    };
}

QByteArray readFile(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The program a command line runs and, for gnss-cli, its command.
QStringList helpArgsFor(const QString &text, QString &program) {
    const QString line = text.mid(text.indexOf("gnss-"));
    const QStringList words = line.split(' ', Qt::SkipEmptyParts);
    program = words.value(0);
    if (program == "gnss-cli" && words.size() > 1 && !words[1].startsWith('-'))
        return {words[1] == "help" ? words.value(2) : words[1], "--help"};
    return {"--help"};
}

// A line of the output a document shows, as a pattern: "..." stands for anything, and digits
// for any number where the line's words do not pin them (a device's number, a speed).
QRegularExpression shownPattern(const QString &line) {
    QString p = QRegularExpression::escape(line.trimmed());
    p.replace(QStringLiteral("\\.\\.\\."), QStringLiteral(".*"));
    p.replace(QRegularExpression(QStringLiteral("[0-9]+(\\\\\\.[0-9]+)?")),
              QStringLiteral("[0-9]+(\\.[0-9]+)?"));
    return QRegularExpression(QStringLiteral("^") + p + QStringLiteral("$"));
}

} // namespace

class TstDocsCommands : public QObject {
    Q_OBJECT

    QList<DocCommand> commands_;
    QTemporaryDir dir_;
    QHash<QString, QByteArray> help_; // "program args" -> its --help

    QString programPath(const QString &program) const {
        if (program == "gnss-cli") return QStringLiteral(GNSS_CLI_PATH);
#ifdef GNSS_SIM_PATH
        if (program == "gnss-sim") return QStringLiteral(GNSS_SIM_PATH);
#endif
#ifdef GNSS_WORKBENCH_PATH
        if (program == "gnss-workbench") return QStringLiteral(GNSS_WORKBENCH_PATH);
#endif
        return {};
    }

    Run sh(const QString &command, int timeoutMs = 60000) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        QStringList path;
        for (const char *p : {"gnss-cli", "gnss-sim", "gnss-workbench"})
            if (const QString at = programPath(p); !at.isEmpty())
                path << QFileInfo(at).absolutePath();
        env.insert("PATH", path.join(':') + ':' + env.value("PATH"));
        env.insert("XDG_CONFIG_HOME", dir_.filePath("config")); // the window's settings
        // bash: the documents' printf examples use its \x escapes.
        return gnss::test::runProgram("bash", {"-c", command}, {}, timeoutMs, env, dir_.path());
    }

private slots:
    void initTestCase() {
        for (const char *name : {"README.md", "docs/cli.md"}) {
            const QByteArray text = readFile(QStringLiteral(GNSS_SOURCE_DIR "/") + name);
            QVERIFY2(!text.isEmpty(), name);
            commands_ += commandsOf(name, QString::fromUtf8(text));
        }
        QVERIFY(dir_.isValid());
#ifdef GNSS_SIM_PATH
        // drive.nmea as docs/cli.md makes it: an hour of a simulated NV08C-RTK rover.
        const Run made = sh(QStringLiteral("gnss-sim --dialect nvs --internal-base --stdout "
                                           "--speed 1000 --duration 3600 > drive.nmea && "
                                           "cp drive.nmea yesterday.nmea && gnss-sim --dialect "
                                           "nvs --stdout --speed 1000 --duration 60 > "
                                           "minute.nmea && ") +
                            kCompareA + " && " + kCompareB);
        QVERIFY2(QFileInfo(dir_.filePath("drive.nmea")).size() > 100000, made.err.constData());
#endif
    }

    // Every command the documents show is in the table, and every row of the table is shown.
    void everyDocumentedCommandIsKnown() {
        const auto known = table();
        QStringList unknown, seen;
        for (const DocCommand &c : commands_) {
            seen << c.text;
            if (!known.contains(c.text) && !c.inText) unknown << c.file + ": " + c.text;
        }
        QVERIFY2(unknown.isEmpty(), qPrintable("not in the table:\n" + unknown.join('\n')));
        QStringList gone;
        for (auto it = known.begin(); it != known.end(); ++it)
            if (!seen.contains(it.key())) gone << it.key();
        QVERIFY2(gone.isEmpty(), qPrintable("no longer in the documents:\n" + gone.join('\n')));
    }

    // The options every documented line names are its program's (or command's).
    void everyDocumentedOptionIsTheProgramsOwn_data() {
        QTest::addColumn<QString>("text");
        for (const DocCommand &c : commands_)
            if (c.text.contains("gnss-") && !c.text.startsWith("./quickstart.sh") &&
                !c.text.startsWith("str2str"))
                QTest::newRow(qPrintable(c.text.left(100))) << c.text;
    }
    void everyDocumentedOptionIsTheProgramsOwn() {
        QFETCH(QString, text);
        QString program;
        const QStringList args = helpArgsFor(text, program);
        const QString path = programPath(program);
        if (path.isEmpty()) QSKIP(qPrintable(program + " is not built"));
        const QString key = program + ' ' + args.join(' ');
        if (!help_.contains(key)) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("QT_QPA_PLATFORM", "offscreen");
            help_[key] = gnss::test::runProgram(path, args, {}, 30000, env).out;
        }
        const QByteArray &help = help_[key];
        QVERIFY2(!help.isEmpty(), qPrintable(key));
        static const QRegularExpression option(QStringLiteral("(--[a-z][a-z-]*)"));
        const QString fromProgram = text.mid(text.indexOf(program));
        for (auto m = option.globalMatch(fromProgram); m.hasNext();) {
            const QString o = m.next().captured(1);
            if (program == "gnss-workbench" && (o == "--port" || o == "--help")) continue;
            // The whole option: --epoch is not --epochs.
            const QRegularExpression whole(QRegularExpression::escape(o) + "(?![a-z-])");
            QVERIFY2(whole.match(QString::fromUtf8(help)).hasMatch(),
                     qPrintable(o + " is not in `" + key + "`, named in: " + text));
        }
    }

    // The runnable ones run, end as the table says, and print what the document shows.
    void everyRunnableCommandRuns_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("shown");
        const auto known = table();
        for (const DocCommand &c : commands_)
            if (known.value(c.text, synopsis()).kind == Kind::Run)
                QTest::newRow(qPrintable(c.text.left(100))) << c.text << c.shown;
    }
    void everyRunnableCommandRuns() {
        QFETCH(QString, text);
        QFETCH(QStringList, shown);
        const Treatment t = table().value(text);
        for (const char *p : {"gnss-sim", "gnss-workbench"})
            if (text.contains(p) && programPath(p).isEmpty())
                QSKIP(qPrintable(QString(p) + " not built"));
        QString command = text;
        for (qsizetype i = 0; i + 1 < t.replace.size(); i += 2) {
            const QString &to = t.replace[i + 1];
            command.replace(t.replace[i],
                            to == "%FREE%" ? QString::number(gnss::test::closedPort()) : to);
        }
        if (!t.note.isEmpty()) command = t.note + ' ' + command;
        const Run r = sh(command);
        const QByteArray why = command.toUtf8() + "\nexit " + QByteArray::number(r.exitCode) +
                               "\nstdout: " + r.out.left(3000) + "\nstderr: " + r.err.left(3000);
        QVERIFY2(r.exitCode == t.status, why.constData());
        const QStringList printed = QString::fromUtf8(r.out).split('\n');
        for (const QString &line : shown) {
            if (line.trimmed().isEmpty() || line.trimmed() == "...") continue;
            const QRegularExpression p = shownPattern(line);
            QVERIFY2(std::any_of(printed.begin(), printed.end(),
                                 [&](const QString &l) { return p.match(l.trimmed()).hasMatch(); }),
                     qPrintable("the document shows \"" + line + "\"\n" + why));
        }
    }

    // The README's list of the names --show-dock takes, and the window's --help, name the docks
    // the window has (the list it gives for a name it does not know).
    void theReadmeNamesEveryDockTheWindowShows() {
        const QString path = programPath("gnss-workbench");
        if (path.isEmpty()) QSKIP("gnss-workbench is not built");
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.insert("LC_ALL", "C"); // the texts in English, whatever the user's language
        env.insert("XDG_CONFIG_HOME", dir_.filePath("config"));
        const auto run = [&](const QStringList &args) {
            const Run r = gnss::test::runProgram(path, args, {}, 30000, env, dir_.path());
            return QString::fromUtf8(r.out + r.err).simplified();
        };
        // The names between `from` and `to`: after the start, a ',' or a ';' (and "with a log
        // open also"), backquoted or not.
        const auto names = [](const QString &text, const QString &from, const QString &to) {
            QStringList out;
            const qsizetype at = text.indexOf(from);
            if (at < 0) return out;
            const qsizetype begin = at + from.size();
            const QString list = text.mid(begin, text.indexOf(to, begin) - begin);
            static const QRegularExpression name(
                    QStringLiteral("(?:^|[,;]|`)\\s*(?:with a log open also\\s*)?`?([a-zA-Z]+)"));
            for (auto m = name.globalMatch(list); m.hasNext();) out << m.next().captured(1);
            out.removeDuplicates();
            return out;
        };
        const QString unknown = run({"--show-dock", "nosuchdock"});
        const QStringList docks = names(unknown, "(use", ")");
        QVERIFY2(docks.size() > 10, qPrintable(unknown));
        const QStringList inHelp = names(run({"--help"}), "tab group:", " --");
        const QStringList inReadme =
                names(QString::fromUtf8(readFile(QStringLiteral(GNSS_SOURCE_DIR "/README.md")))
                              .simplified(),
                      "`--show-dock NAME` brings one to the front (", ").");
        for (const auto &[what, listed] :
             {std::pair{"README.md", inReadme}, std::pair{"--help", inHelp}}) {
            QStringList missing, extra;
            for (const QString &n : docks)
                if (!listed.contains(n)) missing << n;
            for (const QString &n : listed)
                if (!docks.contains(n)) extra << n;
            QVERIFY2(missing.isEmpty() && extra.isEmpty(),
                     qPrintable(QString(what) + " lacks: " + missing.join(", ") +
                                "; names what is no dock: " + extra.join(", ")));
        }
    }
};

QTEST_GUILESS_MAIN(TstDocsCommands)
#include "tst_docs_commands.moc"
