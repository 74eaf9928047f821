#include "gui/connection_bar.h"

#include "core/baud_rates.h"
#include "core/dialect_registry.h"
#include "link/port_watcher.h"
#include "link/tcp_transport.h"

#include <QComboBox>
#include <QFileDialog>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace gnss::app {

ConnectionBar::ConnectionBar(link::PortWatcher *ports, const DialectRegistry &registry,
                             QStringList simulated, QWidget *parent)
    : QToolBar(tr("Connection"), parent), ports_(ports), registry_(registry),
      simulated_(std::move(simulated)) {
    setObjectName("connectionBar");
    addWidget(new QLabel(tr("Source "), this));
    source_ = new QComboBox(this);
    source_->setObjectName("sourceCombo");
    source_->setMinimumContentsLength(28);
    source_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    addWidget(source_);
    addWidget(new QLabel(tr("  Baud "), this));
    baud_ = new QComboBox(this);
    baud_->setObjectName("baudCombo");
    baud_->addItem(tr("auto"), 0);
    for (int b : kStandardBauds) baud_->addItem(QString::number(b), b);
    addWidget(baud_);
    baudNote_ = new QLabel(this);
    baudNote_->setObjectName("baudNote");
    addWidget(baudNote_);
    button_ = new QPushButton(tr("Connect"), this);
    button_->setObjectName("connectButton");
    addWidget(button_);
    add_ = new QPushButton(tr("Add receiver"), this);
    add_->setObjectName("addReceiverButton");
    add_->setToolTip(tr("Connect the source chosen as another receiver: the one shown keeps "
                        "running"));
    addWidget(add_);
    connect(add_, &QPushButton::clicked, this, [this] { emit addRequested(selection()); });
    connect(button_, &QPushButton::clicked, this, [this] {
        if (connected_)
            emit disconnectRequested();
        else
            emit connectRequested(selection());
    });
    connect(source_, &QComboBox::activated, this, [this](int i) {
        const QString action = source_->itemData(i).toString();
        if (!isAskingItem(action)) { // a source: what Connect and Add receiver take
            last_ = selection();
            baud_->setEnabled(last_.kind == SourceSpec::Kind::Serial);
            return;
        }
        // An item that asks for its source: the one given is chosen, a cancel goes back (with
        // the baud shown now).
        SourceSpec back = last_;
        if (back.kind == SourceSpec::Kind::Serial) back.baud = baud_->currentData().toInt();
        SourceSpec chosen = askForSource(action);
        if (chosen.kind == SourceSpec::Kind::Serial) chosen.baud = back.baud;
        if (chosen.valid()) extra_ = chosen;
        rebuildSources();
        select(chosen.valid() ? chosen : back);
    });
    if (ports_)
        connect(ports_, &link::PortWatcher::portsChanged, this, &ConnectionBar::rebuildSources);
    rebuildSources();
    last_ = selection();
    // The wheel and the arrow keys step through the items: they would open a dialog on passing
    // "Port by path…" (and change the source under a connected receiver's bar). The list is
    // chosen from when opened.
    source_->installEventFilter(this);
}

bool ConnectionBar::isAskingItem(const QString &data) {
    for (const char *action : {"port?", "tcp?", "gpsd?", "replay?"})
        if (data == QLatin1String(action)) return true;
    return false;
}

bool ConnectionBar::eventFilter(QObject *watched, QEvent *e) {
    if (watched == source_ && e->type() == QEvent::Wheel) return true;
    if (watched == source_ && e->type() == QEvent::KeyPress) {
        switch (static_cast<QKeyEvent *>(e)->key()) {
        case Qt::Key_Up:
        case Qt::Key_Down:
        case Qt::Key_PageUp:
        case Qt::Key_PageDown:
        case Qt::Key_Home:
        case Qt::Key_End:
            if (!static_cast<QKeyEvent *>(e)->modifiers().testFlag(Qt::AltModifier)) {
                source_->showPopup();
                return true;
            }
            break;
        default: break;
        }
    }
    return QToolBar::eventFilter(watched, e);
}

SourceSpec ConnectionBar::askForSource(const QString &action) {
    bool ok = false;
    if (action == QLatin1String("tcp?")) {
        const QString hp =
                QInputDialog::getText(this, tr("TCP source"), tr("Host and port (HOST:PORT):"),
                                      QLineEdit::Normal, QStringLiteral("127.0.0.1:5000"), &ok)
                        .trimmed();
        QString host;
        quint16 port = 0;
        if (ok && !hp.isEmpty() && !link::TcpTransport::parseHostPort(hp, host, port)) {
            // Said now, not as a failed connection later.
            QMessageBox::warning(this, tr("TCP source"),
                                 tr("'%1' is not HOST:PORT with a port from 1 to 65535.").arg(hp));
            return {};
        }
        if (ok && !hp.isEmpty()) return {SourceSpec::Kind::Tcp, hp};
    } else if (action == QLatin1String("port?")) {
        // A port the system does not list: a stable /dev/serial/by-id name, a Bluetooth rfcomm
        // device, a pseudo-terminal (gnss-sim --pty, socat).
        const QString path = QInputDialog::getText(this, tr("Serial port by path"),
                                                   tr("Device path (/dev/serial/by-id/…, "
                                                      "/dev/rfcomm0, /dev/pts/3):"),
                                                   QLineEdit::Normal, QStringLiteral("/dev/"), &ok)
                                     .trimmed();
        if (ok && !path.isEmpty() && path != QLatin1String("/dev/"))
            return {SourceSpec::Kind::Serial, path};
    } else if (action == QLatin1String("gpsd?")) {
        // A receiver that gpsd holds: gpsd on this machine unless told otherwise.
        const QString where =
                QInputDialog::getText(this, tr("gpsd source"),
                                      tr("gpsd's host, port and device (HOST[:PORT][/DEVICE]; "
                                         "port 2947 and every device when left out):"),
                                      QLineEdit::Normal, QStringLiteral("localhost"), &ok)
                        .trimmed();
        if (ok && !where.isEmpty()) return {SourceSpec::Kind::Gpsd, where};
    } else if (action == QLatin1String("replay?")) {
        const QString f = QFileDialog::getOpenFileName(
                this, tr("Open Log"), {}, tr("NMEA logs (*.nmea *.log *.txt);;All files (*)"));
        if (!f.isEmpty()) return {SourceSpec::Kind::Replay, f};
    }
    return {};
}

void ConnectionBar::rebuildSources() {
    const SourceSpec current = selection();
    source_->clear();
    if (ports_) {
        for (const link::PortInfo &p : ports_->ports()) {
            QString text = p.portName;
            if (!p.description.isEmpty()) text += QStringLiteral(" — ") + p.description;
            if (!p.usbId().isEmpty()) text += QStringLiteral(" [%1]").arg(p.usbId());
            source_->addItem(text,
                             SourceSpec{SourceSpec::Kind::Serial, p.systemLocation}.toString());
            source_->setItemData(source_->count() - 1,
                                 tr("%1\nManufacturer: %2\nSerial number: %3")
                                         .arg(p.systemLocation, p.manufacturer, p.serialNumber),
                                 Qt::ToolTipRole);
        }
    }
    // The simulated receivers: one per dialect the simulator plays, named by its record.
    for (const QString &id : simulated_) {
        const Dialect *d = registry_.find(id.toStdString());
        const QString name =
                d ? QString::fromUtf8(d->displayName.data(), qsizetype(d->displayName.size())) : id;
        source_->addItem(tr("Simulated %1").arg(name),
                         SourceSpec{SourceSpec::Kind::Simulator, id}.toString());
    }
    if (extra_.valid()) source_->addItem(extra_.displayName(), extra_.toString());
    source_->addItem(tr("Port by path…"), QStringLiteral("port?"));
    source_->addItem(tr("TCP…"), QStringLiteral("tcp?"));
    source_->addItem(tr("gpsd…"), QStringLiteral("gpsd?"));
    source_->addItem(tr("Open log…"), QStringLiteral("replay?"));
    select(extra_.valid() && (current.kind == SourceSpec::Kind::None) ? extra_ : current);
}

SourceSpec ConnectionBar::selection() const {
    SourceSpec s = SourceSpec::fromString(source_->currentData().toString());
    if (s.kind == SourceSpec::Kind::Serial) s.baud = baud_->currentData().toInt();
    return s;
}

void ConnectionBar::select(const SourceSpec &spec) {
    if (!spec.valid()) return;
    SourceSpec key = spec;
    if (key.kind == SourceSpec::Kind::Serial) key.baud = 0;
    int i = source_->findData(key.toString());
    if (i < 0 && (spec.kind == SourceSpec::Kind::Tcp || spec.kind == SourceSpec::Kind::Replay ||
                  spec.kind == SourceSpec::Kind::Gpsd || spec.kind == SourceSpec::Kind::Serial)) {
        // Not listed (a TCP/gpsd/replay source from the command line, or a port not present now).
        source_->insertItem(0, spec.displayName(), key.toString());
        i = 0;
    }
    if (i >= 0) {
        source_->setCurrentIndex(i);
        last_ = spec;
    }
    if (spec.kind == SourceSpec::Kind::Serial) {
        const int b = baud_->findData(spec.baud);
        baud_->setCurrentIndex(b >= 0 ? b : 0);
    }
    baud_->setEnabled(spec.kind == SourceSpec::Kind::Serial);
}

void ConnectionBar::setBaudNote(const QString &text, const QString &tooltip) {
    baudNote_->setText(text.isEmpty() ? QString() : QStringLiteral(" %1 ").arg(text));
    baudNote_->setToolTip(tooltip);
}

void ConnectionBar::setConnected(bool connected) {
    connected_ = connected;
    button_->setText(connected ? tr("Disconnect") : tr("Connect"));
    // The source stays choosable while connected: what Add receiver connects.
    baud_->setEnabled(selection().kind == SourceSpec::Kind::Serial);
}

} // namespace gnss::app
