#include "link/gpsd_transport.h"

#include "link/while_closing.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace gnss::link {

namespace {

bool parsePort(const QString &text, quint16 &port) {
    bool ok = false;
    const uint p = text.toUInt(&ok);
    if (!ok || p == 0 || p > 65535) return false;
    port = static_cast<quint16>(p);
    return true;
}
} // namespace

bool GpsdTransport::parseTarget(const QString &text, Target &out, QString *error) {
    auto refuse = [&](const QString &why) {
        if (error) *error = why;
        return false;
    };
    Target t;
    QString s = text.trimmed();
    if (s.startsWith(QLatin1String("gpsd://"), Qt::CaseInsensitive)) s = s.mid(7);
    if (s.isEmpty() || s.contains(QLatin1Char(' ')))
        return refuse(tr("a gpsd source is HOST[:PORT][/DEVICE], got '%1'").arg(text));
    // The device is the path after the host part: the first '/' (past an IPv6 literal's ']').
    const qsizetype bracket = s.startsWith(QLatin1Char('[')) ? s.indexOf(QLatin1Char(']')) : 0;
    if (bracket < 0) return refuse(tr("a gpsd source is HOST[:PORT][/DEVICE], got '%1'").arg(text));
    const qsizetype slash = s.indexOf(QLatin1Char('/'), bracket);
    const QString hostPort = slash < 0 ? s : s.left(slash);
    if (slash >= 0 && slash + 1 < s.size()) t.device = s.mid(slash);

    QString host, port;
    if (hostPort.startsWith(QLatin1Char('['))) { // [v6] or [v6]:port
        const QString rest = hostPort.mid(bracket + 1);
        host = hostPort.mid(1, bracket - 1);
        if (rest.startsWith(QLatin1Char(':')))
            port = rest.mid(1);
        else if (!rest.isEmpty())
            return refuse(tr("a gpsd source is HOST[:PORT][/DEVICE], got '%1'").arg(text));
    } else if (hostPort.count(QLatin1Char(':')) == 1) { // host:port, or :port
        host = hostPort.section(QLatin1Char(':'), 0, 0);
        port = hostPort.section(QLatin1Char(':'), 1);
    } else { // a name, an IPv4 address or a bare IPv6 address: no port
        host = hostPort;
    }
    if (!host.isEmpty()) t.host = host;
    if (!port.isEmpty() && !parsePort(port, t.port))
        return refuse(tr("gpsd's port is a number from 1 to 65535, got '%1'").arg(port));
    out = t;
    return true;
}

QByteArray GpsdTransport::watchRequest(const QString &device) {
    // json:false: gpsd's own reports (TPV, SKY) are not wanted, only the receiver's sentences.
    QJsonObject watch{{"enable", true}, {"json", false}, {"raw", 1}};
    if (!device.isEmpty()) watch.insert("device", device);
    return "?WATCH=" + QJsonDocument(watch).toJson(QJsonDocument::Compact) + "\n";
}

GpsdTransport::GpsdTransport(Target target, QObject *parent)
    : Transport(parent), target_(std::move(target)) {
    connectTimer_.setSingleShot(true);
    connectTimer_.setInterval(kDefaultConnectTimeoutMs);
    connect(&connectTimer_, &QTimer::timeout, this, [this] {
        if (state() != State::Connecting) return;
        failOpening(phase_ == Phase::AwaitVersion && socket_.state() != QTcpSocket::ConnectedState
                            ? tr("no answer within %1 s").arg(connectTimer_.interval() / 1000.0)
                            : tr("gpsd did not answer the watch request within %1 s")
                                      .arg(connectTimer_.interval() / 1000.0));
    });
    connect(&socket_, &QTcpSocket::readyRead, this, &GpsdTransport::onReadyRead);
    connect(&socket_, &QTcpSocket::disconnected, this, [this] {
        if (closing_) return;
        if (state() == State::Connecting) {
            failOpening(tr("gpsd closed the connection"));
        } else if (state() == State::Open) {
            phase_ = Phase::Idle;
            fail(tr("%1: gpsd closed the connection").arg(description()), true);
        }
    });
    connect(&socket_, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
        if (closing_) return;
        if (state() == State::Connecting) {
            failOpening(e == QAbstractSocket::ConnectionRefusedError
                                ? tr("%1 (is gpsd running?)").arg(socket_.errorString())
                                : socket_.errorString());
            return;
        }
        if (e == QAbstractSocket::RemoteHostClosedError) return; // disconnected() says it
        if (state() == State::Open) {
            phase_ = Phase::Idle;
            fail(tr("%1: %2").arg(description(), socket_.errorString()), true);
        }
    });
}

GpsdTransport::~GpsdTransport() {
    closing_ = true;
    socket_.abort();
}

void GpsdTransport::abortSocket() {
    whileClosing(closing_, [this] { socket_.abort(); });
}

bool GpsdTransport::open() {
    abortSocket();
    reader_.reset();
    release_.clear();
    devices_.clear();
    phase_ = Phase::AwaitVersion;
    setState(State::Connecting);
    connectTimer_.start();
    socket_.connectToHost(target_.host, target_.port); // answers arrive as signals
    return state() != State::Closed;
}

void GpsdTransport::close() {
    connectTimer_.stop();
    abortSocket();
    phase_ = Phase::Idle;
    setState(State::Closed);
}

void GpsdTransport::failOpening(const QString &why, bool request) {
    connectTimer_.stop();
    abortSocket();
    phase_ = Phase::Idle;
    const QString message = tr("Cannot connect to %1: %2").arg(description(), why);
    if (request)
        failRequest(message);
    else
        fail(message, false);
}

void GpsdTransport::failNoSuchDevice() {
    failOpening(devices_.isEmpty()
                        ? tr("gpsd has no device %1 (it has none)").arg(target_.device)
                        : tr("gpsd has no device %1 (it has %2)")
                                  .arg(target_.device, devices_.join(QStringLiteral(", "))),
                true);
}

void GpsdTransport::onReadyRead() {
    const quint64 droppedBefore = reader_.linesDropped();
    std::vector<QJsonObject> reports;
    const QByteArray sentences = reader_.feed(socket_.readAll(), reports);
    if (phase_ == Phase::AwaitVersion &&
        (!sentences.isEmpty() || reader_.linesDropped() != droppedBefore ||
         (!reports.empty() && reports.front().value("class").toString() != "VERSION"))) {
        // Something else listens there (a receiver's TCP server, another service).
        failOpening(tr("this is not gpsd: it did not greet with its VERSION"));
        return;
    }
    for (const QJsonObject &r : reports) {
        onReport(r);
        if (phase_ == Phase::Idle) return; // the opening failed on this report
    }
    // Sentences count once the watch is confirmed; before that they belong to no request of ours.
    if (phase_ == Phase::Streaming && !sentences.isEmpty()) emit bytesReceived(sentences);
}

void GpsdTransport::onReport(const QJsonObject &report) {
    const QString cls = report.value("class").toString();
    if (cls == QLatin1String("VERSION")) {
        release_ = report.value("release").toString();
        if (phase_ != Phase::AwaitVersion) return;
        phase_ = Phase::AwaitWatch;
        socket_.write(watchRequest(target_.device));
    } else if (cls == QLatin1String("DEVICES")) {
        devices_.clear();
        for (const QJsonValue &d : report.value("devices").toArray())
            devices_ << d.toObject().value("path").toString();
        if (phase_ == Phase::AwaitDevices ||
            (phase_ == Phase::AwaitWatch && !target_.device.isEmpty() &&
             !devices_.contains(target_.device)))
            failNoSuchDevice();
    } else if (cls == QLatin1String("DEVICE")) {
        // A device gpsd opened or closed later (hotplug): keep the list current.
        const QString path = report.value("path").toString();
        if (report.contains("activated") && report.value("activated").toDouble() == 0)
            devices_.removeAll(path);
        else if (!path.isEmpty() && !devices_.contains(path))
            devices_ << path;
    } else if (cls == QLatin1String("WATCH")) {
        if (phase_ != Phase::AwaitWatch) return;
        phase_ = Phase::Streaming;
        connectTimer_.stop();
        setState(State::Open);
    } else if (cls == QLatin1String("ERROR")) {
        const QString message = report.value("message").toString();
        if (phase_ == Phase::AwaitWatch && !target_.device.isEmpty() &&
            message.startsWith(QLatin1String("No such device"))) {
            // gpsd refuses the watch before listing its devices: ask for them, to name them.
            phase_ = Phase::AwaitDevices;
            socket_.write(QByteArrayLiteral("?DEVICES;\n"));
        } else if (phase_ == Phase::AwaitDevices) {
            failNoSuchDevice();
        } else if (phase_ != Phase::Streaming)
            failOpening(tr("gpsd refused: %1").arg(message));
        else
            fail(tr("%1: gpsd says: %2").arg(description(), message), false);
    }
}

QString GpsdTransport::description() const {
    const QString host = target_.host.contains(QLatin1Char(':'))
                                 ? QStringLiteral("[%1]").arg(target_.host)
                                 : target_.host;
    const QString where = QStringLiteral("%1:%2").arg(host).arg(target_.port);
    return target_.device.isEmpty() ? tr("gpsd at %1").arg(where)
                                    : tr("gpsd at %1, %2").arg(where, target_.device);
}

QString GpsdTransport::readOnlyReason() const {
    return tr("gpsd owns the port: commands cannot be sent to a receiver read through gpsd");
}

} // namespace gnss::link
