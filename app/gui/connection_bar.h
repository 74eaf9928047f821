#pragma once
// ConnectionBar: where the data comes from — serial ports (refreshed by themselves when a device
// is plugged or unplugged), the built-in simulated receivers, TCP, gpsd, a log to replay — the
// baud rate with "auto", and Connect / Disconnect.
#include "link/source_spec.h"

#include <QStringList>
#include <QToolBar>

class QComboBox;
class QLabel;
class QPushButton;

namespace gnss {
class DialectRegistry;
namespace link {
class PortWatcher;
}
} // namespace gnss

namespace gnss::app {

using link::SourceSpec;

class ConnectionBar : public QToolBar {
    Q_OBJECT
public:
    // `simulated`: the dialects the built-in simulator plays (listed as sources).
    ConnectionBar(link::PortWatcher *ports, const DialectRegistry &registry, QStringList simulated,
                  QWidget *parent = nullptr);

    SourceSpec selection() const;
    void select(const SourceSpec &spec);
    void setConnected(bool connected);
    // A note beside the baud rate: the rate being tried, the rate found ("auto → 38400").
    void setBaudNote(const QString &text, const QString &tooltip = {});

signals:
    void connectRequested(const gnss::link::SourceSpec &spec);
    void disconnectRequested();
    // Another receiver, on the source chosen (the one shown keeps its own).
    void addRequested(const gnss::link::SourceSpec &spec);

private:
    bool eventFilter(QObject *watched, QEvent *e) override;
    static bool isAskingItem(const QString &data);
    void rebuildSources();
    // Asks for the source of an item that stands for a dialog ("tcp?", "port?", "gpsd?",
    // "replay?"); invalid when cancelled.
    SourceSpec askForSource(const QString &action);
    link::PortWatcher *ports_;
    const DialectRegistry &registry_;
    QStringList simulated_;
    QComboBox *source_;
    QComboBox *baud_;
    QLabel *baudNote_;
    QPushButton *button_;
    QPushButton *add_;
    bool connected_ = false;
    SourceSpec extra_; // a TCP, gpsd, replay or unlisted serial source chosen by the user
    SourceSpec last_;  // the source chosen last: where a cancelled dialog goes back to
};

} // namespace gnss::app
