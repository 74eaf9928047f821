#include "gui/play_out_dialog.h"

#include "core/baud_rates.h"
#include "gui/log_player.h"
#include "gui/log_viewer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSpinBox>
#include <QVBoxLayout>

namespace gnss::app {

PlayOutDialog::PlayOutDialog(LogViewer *viewer, LogPlayer *player, QWidget *parent)
    : QDialog(parent), viewer_(viewer), player_(player) {
    setWindowTitle(tr("Play Out"));
    setObjectName("playOutDialog");
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("Send the log to other software at its own pace, as a receiver "
                                "would: the bytes exactly as in the file."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    auto *form = new QFormLayout;
    range_ = new QLabel(this);
    form->addRow(tr("Epochs:"), range_);
    kind_ = new QComboBox(this);
    kind_->setObjectName("playOutKind");
    kind_->addItem(tr("A new pseudo-terminal"), int(LogPlayer::Target::Kind::Pty));
    kind_->addItem(tr("A TCP server on 127.0.0.1"), int(LogPlayer::Target::Kind::Tcp));
    kind_->addItem(tr("A serial port"), int(LogPlayer::Target::Kind::Serial));
    form->addRow(tr("To:"), kind_);
    tcpPort_ = new QSpinBox(this);
    tcpPort_->setObjectName("playOutTcpPort");
    tcpPort_->setRange(1, 65535);
    tcpPort_->setValue(10110);
    form->addRow(tr("TCP port:"), tcpPort_);
    serialPort_ = new QComboBox(this);
    serialPort_->setEditable(true);
    for (const QSerialPortInfo &p : QSerialPortInfo::availablePorts())
        serialPort_->addItem(p.systemLocation());
    form->addRow(tr("Serial port:"), serialPort_);
    baud_ = new QComboBox(this);
    for (int b : kStandardBauds) baud_->addItem(QString::number(b), b);
    baud_->setCurrentText(QStringLiteral("9600"));
    form->addRow(tr("Baud rate:"), baud_);
    speed_ = new QDoubleSpinBox(this);
    speed_->setObjectName("playOutSpeed");
    speed_->setRange(0.1, 100);
    speed_->setDecimals(1);
    speed_->setValue(1);
    speed_->setSuffix(tr("×"));
    form->addRow(tr("Speed:"), speed_);
    loop_ = new QCheckBox(tr("Start again at the end"), this);
    loop_->setObjectName("playOutLoop");
    form->addRow(QString(), loop_);
    layout->addLayout(form);
    status_ = new QLabel(this);
    status_->setObjectName("playOutStatus");
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(status_);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    start_ = buttons->addButton(tr("Start"), QDialogButtonBox::ActionRole);
    start_->setObjectName("playOutStart");
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(start_, &QPushButton::clicked, this, [this] {
        if (player_->running())
            player_->stop();
        else
            startPlaying();
    });
    connect(kind_, &QComboBox::currentIndexChanged, this, &PlayOutDialog::updateState);
    connect(player_, &LogPlayer::statusChanged, this, &PlayOutDialog::updateState);
    updateState();
}

bool PlayOutDialog::startPlaying() {
    LogPlayer::Target t;
    t.kind = static_cast<LogPlayer::Target::Kind>(kind_->currentData().toInt());
    t.tcpPort = quint16(tcpPort_->value());
    t.serialPort = serialPort_->currentText().trimmed();
    t.baud = baud_->currentData().toInt();
    const auto [first, last] = viewer_->cursor()->selection();
    QString why;
    if (!player_->start(viewer_->shared(), first, last, speed_->value(), loop_->isChecked(), t,
                        &why)) {
        status_->setText(tr("Not started: %1").arg(why));
        return false;
    }
    updateState();
    return true;
}

void PlayOutDialog::updateState() {
    const auto kind = static_cast<LogPlayer::Target::Kind>(kind_->currentData().toInt());
    const bool running = player_->running();
    tcpPort_->setEnabled(!running && kind == LogPlayer::Target::Kind::Tcp);
    serialPort_->setEnabled(!running && kind == LogPlayer::Target::Kind::Serial);
    baud_->setEnabled(!running && kind == LogPlayer::Target::Kind::Serial);
    kind_->setEnabled(!running);
    speed_->setEnabled(!running);
    loop_->setEnabled(!running);
    start_->setText(running ? tr("Stop") : tr("Start"));
    const bool open = viewer_->isOpen() && !viewer_->cursor()->empty();
    start_->setEnabled(running || open);
    if (open) {
        const auto [first, last] = viewer_->cursor()->selection();
        range_->setText(viewer_->cursor()->hasRange()
                                ? tr("%1 to %2 (the selected range)").arg(first).arg(last)
                                : tr("%1 to %2 (the whole log)").arg(first).arg(last));
    } else {
        range_->setText(tr("no log is open"));
    }
    if (running || !status_->text().startsWith(tr("Not started: %1").arg(QString())))
        status_->setText(player_->statusText());
}

} // namespace gnss::app
