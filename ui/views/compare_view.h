#pragma once
// CompareView: the Compare dock. Two or more receivers on the same sky, matched epoch by epoch
// on UTC time (CompareModel); the first is the reference. Its tabs:
//   Summary: per receiver after the first, the position difference (east, north, up, horizontal:
//            mean, median, p95; CEP50, CEP95), the C/N0 difference over every signal both track
//            and per constellation, satellites only one of the two had, fix availability;
//   Signals: per satellite and signal, each receiver's C/N0 side by side and the differences
//            ("—" where a receiver does not track it);
//   Plots:   the scatter, the differences over time and the fix strips (ComparePlot).
// Every number is over the window chosen (the last 1, 5, 15 or 60 minutes); Export saves it.
#include <QWidget>

class QComboBox;
class QTabWidget;
class QTableWidget;

namespace gnss::ui {

class CompareModel;
class ComparePlot;

class CompareView : public QWidget {
    Q_OBJECT
public:
    explicit CompareView(CompareModel *model, QWidget *parent = nullptr);

    // Fills the tables from the model now (the model's changed() does it twice a second).
    void refresh();
    QTableWidget *summary() const { return summary_; }
    // The summary's corner: how many epochs the numbers are over.
    QString note() const { return note_; }
    QTableWidget *signalTable() const { return signals_; }
    ComparePlot *plot() const { return plot_; }

signals:
    // Export chosen: CSV (one row per match) or JSON (the report over the window).
    void exportRequested(bool json);

private:
    void fillSummary();
    void fillSignals();

    CompareModel *model_;
    QString note_;
    QComboBox *window_, *receiver_;
    QTabWidget *tabs_;
    QTableWidget *summary_, *signals_;
    ComparePlot *plot_;
};

} // namespace gnss::ui
