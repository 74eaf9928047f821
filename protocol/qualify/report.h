#pragma once
// The qualification report to hand over: one self-contained HTML file or a PDF (the same
// content, laid out by QTextDocument on a QPdfWriter; no display needed, the offscreen platform
// does), with beside it the runs as CSV and the whole campaign as JSON for the user's own tools.
// Receiver identity (model, firmware, port, baud), its settings as read back, the conditions
// (date, duration, reference point, location), per receiver and kind of start the TTFF table and
// its CDF plot, the limits with pass or fail, the accuracy against the reference with its
// histogram, and every run as a row. Texts through tr() (the user's language); lengths in the
// unit given (the preferences').
#include "compare/accuracy.h"
#include "qualify/limits.h"
#include "qualify/plots.h"
#include "qualify/ttff.h"

#include <QColor>
#include <QDateTime>
#include <QString>
#include <QStringList>

#include <optional>
#include <utility>
#include <vector>

namespace gnss::qualify {

struct ReportReceiver {
    QString name;            // the dialect's display name ("NVS NV08C-RTK")
    QString model, firmware; // as identified (empty: not reported)
    QString port;            // "/dev/ttyUSB0", "192.168.1.20:4001", "simulated nvs"
    int baud = 0;            // 0: not a serial port
    std::vector<std::pair<QString, QString>> settings; // label → value, as read back
    std::vector<TtffRun> runs;
    std::optional<compare::AccuracyReport> accuracy;
    std::vector<double> horizontalErrors; // metres, for the histogram and the errors over time
    std::vector<double> verticalErrors;   // |up| metres in the same order, NaN: no height
};

struct LengthUnit {
    QString symbol = QStringLiteral("m");
    double perMetre = 1.0; // units in a metre (3.28084 for feet)
};

struct ReportInput {
    QDateTime started, ended;
    std::optional<compare::ReferencePoint> reference;
    QString location; // in words, as the user's preferences show a position; may be empty
    std::vector<ReceiverAction> starts;
    int runsPerStart = 0;
    double timeoutS = 0, pauseS = 0;
    std::vector<Limit> limits;
    std::vector<ReportReceiver> receivers;
    LengthUnit length;
};

enum class ReportFormat { Pdf, Html };
// By the file's extension (.pdf, .html, .htm; any case); nullopt for another.
std::optional<ReportFormat> reportFormatOf(const QString &path);

// The report as one self-contained XHTML document (well-formed XML: plots as data: PNG images,
// styles inline).
QString reportHtml(const ReportInput &in);
// Every run of every receiver, one row each, header first (receiver, start, run, outcome, the
// times in seconds, satellites, distance in metres).
QByteArray runsCsv(const ReportInput &in);
// {"receivers": [{"name", "model", "firmware", "port", "baud", campaign JSON, "limits"}], ...}
QByteArray campaignJson(const ReportInput &in);

// Writes the report at `path` (PDF or HTML by its extension) and the runs beside it as
// BASE.csv and BASE.json; the files written, or an empty list with `error` in words.
QStringList writeReport(const ReportInput &in, const QString &path, QString *error);

} // namespace gnss::qualify
