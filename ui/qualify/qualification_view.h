#pragma once
// QualificationView: the Qualification dock. A time-to-first-fix campaign asked for (the kinds
// of start, runs, timeout, pause, hold, limits such as "cold:mean<=60"; on the selected receiver
// or on every one at once, with the same restarts), its progress (a line per receiver and a bar:
// run i of N, elapsed, an estimate of the end), cancel, and the results: per receiver and kind of
// start the table with the limits' pass or fail, the CDF plot, every run, and the accuracy
// against the reference (AccuracyPanel, live). Save report writes PDF or HTML. The view checks
// what is typed and says what is wrong before anything is asked; the window's controller runs it.
#include "models/value_format.h"
#include "qualify/limits.h"
#include "qualify/report.h"
#include "qualify/ttff_campaign.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;
class QTableWidget;

namespace gnss::ui {

class AccuracyPanel;
class CdfPlot;

struct QualificationRequest {
    qualify::TtffCampaign::Plan plan;
    std::vector<qualify::Limit> limits;
    bool allReceivers = false;
};

class QualificationView : public QWidget {
    Q_OBJECT
public:
    explicit QualificationView(QWidget *parent = nullptr);

    void setDisplayPrefs(const DisplayPrefs &prefs);
    // Whether a campaign runs (Start off, Cancel on) and whether there are several receivers
    // (the choice of all of them).
    void setRunning(bool running);
    void setReceiverCount(int n);
    // The progress: a line per receiver, runs done of the total, seconds left (estimate; < 0
    // unknown).
    void setProgress(const QStringList &lines, int done, int total, double secondsLeft);
    // The runs so far (per receiver) and the limits they are held to.
    void setResults(const std::vector<qualify::ReportReceiver> &receivers,
                    const std::vector<qualify::Limit> &limits);
    // A refusal or an error, in words (empty clears it).
    void showMessage(const QString &text);
    // The request as typed; nullopt with the reason shown when it is not valid.
    std::optional<QualificationRequest> request();

    AccuracyPanel *accuracy() const { return accuracy_; }
    QTableWidget *resultsTable() const { return results_; }
    QTableWidget *runsTable() const { return runs_; }
    CdfPlot *cdf() const { return cdf_; }
    QTabWidget *tabs() const { return tabs_; }
    QString message() const;

signals:
    void startRequested(const gnss::ui::QualificationRequest &request);
    void cancelRequested();
    void reportRequested(); // Save report chosen (the window asks where)

private:
    DisplayPrefs prefs_;
    QComboBox *scope_;
    QCheckBox *cold_, *warm_, *hot_;
    QSpinBox *runsCount_, *timeout_, *pause_, *hold_;
    QLineEdit *limits_;
    QPushButton *start_, *cancel_, *report_;
    QLabel *progressText_, *message_;
    QProgressBar *bar_;
    QTabWidget *tabs_;
    QTableWidget *results_, *runs_;
    CdfPlot *cdf_;
    AccuracyPanel *accuracy_;
};

} // namespace gnss::ui

Q_DECLARE_METATYPE(gnss::ui::QualificationRequest)
