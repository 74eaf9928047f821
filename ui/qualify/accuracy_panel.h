#pragma once
// AccuracyPanel: positions against a reference — typed (LAT,LON[,HEIGHT], degrees and
// ellipsoidal metres) or, when none is typed, their own mean — as a table (bias east, north, up;
// horizontal mean, median, CEP50, CEP95, 2DRMS, R95, max; vertical mean, median, 95 %; the share
// of epochs within 2 cm .. 5 m, overall and per fix type) beside a histogram of the horizontal
// errors or (chosen above it) the horizontal and vertical errors over time. The Qualification dock
// shows it live; the log viewer's statistics over the range. With a site store (the user's site
// list, shared with gnss-cli), the Sites menu fills the reference with a site's antenna position,
// or keeps the mean of the positions shown (a survey-in by the workbench) as a site.
#include "compare/accuracy.h"
#include "models/value_format.h"

#include <QWidget>

#include <optional>

class QLineEdit;
class QSplitter;
class QToolButton;
class QTableWidget;

namespace gnss::sites {
class SiteStore;
}

namespace gnss::ui {

class ErrorHistogram;
class ErrorSeriesPlot;

class AccuracyPanel : public QWidget {
    Q_OBJECT
public:
    explicit AccuracyPanel(QWidget *parent = nullptr);
    // Modest, whatever its table and plot would like: a dock holding it keeps the width its
    // other views ask for (the log statistics share the sky plot's group on a laptop).
    QSize sizeHint() const override { return {320, 240}; }

    void setUnits(UnitSystem u);
    // The site list to pick references from and save means to (none: no site buttons).
    void setSiteStore(const sites::SiteStore *store);
    // The reference from the site named so (its antenna position); false, with why, if none.
    bool useSite(const QString &name, QString *why = nullptr);
    // Saves the mean of the positions last shown as a site (survey-in by the workbench); false,
    // with why, when there is none or the name is taken or the list cannot be written.
    bool saveMeanAsSite(const QString &name, QString *why = nullptr);
    // The reference typed; nullopt when none is (the mean is used) or it does not parse (an
    // error is shown under the field).
    std::optional<compare::ReferencePoint> reference() const;
    bool referenceValid() const;
    void setReferenceText(const QString &text);
    QString referenceText() const;
    // Measures `positions` against the reference typed or their mean, and shows it.
    void show(const compare::PositionSet &positions);
    // The value beside a row's name ("" when there is no such row).
    QString valueOf(const QString &name) const;
    ErrorHistogram *histogram() const { return histogram_; }
    ErrorSeriesPlot *overTime() const { return overTime_; }
    // The histogram beside the table (default) or under it (a narrow dock).
    void setOrientation(Qt::Orientation o);

signals:
    void referenceChanged();
    void message(const QString &text); // what a site action did, for the status bar

private:
    void addRow(const QString &name, const QString &value);
    void say(const QString &text);
    void clearPlots();
    QString len(double metres, int decimals = 3) const;

    UnitSystem units_ = UnitSystem::Metric;
    QLineEdit *reference_;
    QTableWidget *table_;
    ErrorHistogram *histogram_;
    ErrorSeriesPlot *overTime_;
    QSplitter *split_;
    QToolButton *siteButton_;
    const sites::SiteStore *store_ = nullptr;
    std::optional<compare::ReferencePoint> lastMean_;
    std::optional<double> lastCep95_;
    qsizetype positionsShown_ = 0;
};

} // namespace gnss::ui
