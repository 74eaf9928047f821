#pragma once
// SignalHistoryView: C/N0 of each satellite and signal over time, one line each in its
// constellation's colour; the satellites chosen (typed, "G05 R12", or clicked) are drawn bold and
// labelled, the others faint. Live it shows the last minutes; for a log, the whole log or the
// range selected. Painted with QPainter (cheap with sixty signals at 10 Hz).
#include <QWidget>

#include <set>
#include <string>

class QComboBox;
class QLineEdit;

namespace gnss::ui {

class SignalHistoryModel;

class SignalHistoryView : public QWidget {
    Q_OBJECT
public:
    explicit SignalHistoryView(SignalHistoryModel *model, QWidget *parent = nullptr);
    // The satellites highlighted, by label ("G05"); every signal of each.
    void setHighlighted(const QStringList &labels);
    QStringList highlighted() const;
    // Offers the span (minutes kept) for a live receiver; a log's history shows all it holds.
    void setLive(bool live);

private:
    class Canvas;
    SignalHistoryModel *model_;
    Canvas *canvas_;
    QLineEdit *chosen_;
    QComboBox *span_;
};

} // namespace gnss::ui
