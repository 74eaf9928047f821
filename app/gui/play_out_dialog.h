#pragma once
// Play Out: the dialog that sends the open log (the selected range, or all of it) to other
// software through a LogPlayer: a new pseudo-terminal, a TCP server on 127.0.0.1, or a serial
// port; at a speed factor, optionally looping. It stays open while playing and shows where the
// bytes go (the pseudo-terminal's device to give the other program) and how far it is.
#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace gnss::app {

class LogPlayer;
class LogViewer;

class PlayOutDialog : public QDialog {
    Q_OBJECT
public:
    PlayOutDialog(LogViewer *viewer, LogPlayer *player, QWidget *parent = nullptr);

    // Starts with the choices made (what the Start button does); false and a word when refused.
    bool startPlaying();

private:
    void updateState();

    LogViewer *viewer_;
    LogPlayer *player_;
    QComboBox *kind_, *serialPort_, *baud_;
    QSpinBox *tcpPort_;
    QDoubleSpinBox *speed_;
    QCheckBox *loop_;
    QLabel *range_, *status_;
    QPushButton *start_;
};

} // namespace gnss::app
