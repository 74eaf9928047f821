#pragma once
// LogSummaryView: statistics of the selected range (or of the whole log): its span, availability
// of each fix type, time to first fix and to RTK fixed, gaps, time jumps, checksum errors, the
// position spread (CEP50, CEP95, 2DRMS about the mean) and the worst HDOP. Computed from the
// index alone, so it follows a range being dragged. Below it the accuracy of the range's
// positions against a point typed or their mean (AccuracyPanel: bias, CEP, 2DRMS, R95, shares
// within 2 cm .. 5 m per fix type, histogram), horizontal: the index keeps sea-level heights
// only (`gnss-cli summary --reference` gives the vertical too).
#include "logview/log_cursor.h"
#include "models/value_format.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QTableWidget;
class QTimer;

namespace gnss::ui {

class AccuracyPanel;

class LogSummaryView : public QWidget {
    Q_OBJECT
public:
    explicit LogSummaryView(LogCursor *cursor, QWidget *parent = nullptr);

    void setDisplayPrefs(const DisplayPrefs &prefs);
    const logview::RangeStats &stats() const { return stats_; }
    bool stationaryOnly() const;
    // The value shown beside a row's name ("" when there is no such row).
    QString valueOf(const QString &name) const;
    AccuracyPanel *accuracy() const { return accuracy_; }

signals:
    void exportRequested(); // save the statistics as JSON

private:
    void reload();
    void reloadAccuracy();
    void addRow(const QString &name, const QString &value, const QColor &swatch = {});

    LogCursor *cursor_;
    DisplayPrefs prefs_;
    logview::RangeStats stats_;
    QLabel *title_;
    QCheckBox *stationary_;
    QTableWidget *table_;
    AccuracyPanel *accuracy_;
    QTimer *accuracyLater_; // the accuracy once a dragged range rests
};

} // namespace gnss::ui
