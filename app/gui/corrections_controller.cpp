#include "gui/corrections_controller.h"

#include "corrections/ntrip_source.h"
#include "corrections/rover_position.h"
#include "corrections/tcp_correction_source.h"
#include "gui/password_keychain.h"

#include "link/connection.h"
#include "link/sentence_stream.h"
#include "session/receiver_link.h"
#include "state/epoch.h"

#include <QDateTime>
#include <QSettings>

namespace gnss::app {

namespace {

constexpr int kAgeSampleMs = 1000; // the monitor's age history is sampled once a second

std::int64_t nowMs() {
    return QDateTime::currentMSecsSinceEpoch(); // the clock CorrectionsView reads the monitor by
}

// Where a caster's password is kept: one per user, caster and port.
QString keychainKey(const ui::CorrectionsRequest &r) {
    return QStringLiteral("ntrip:%1@%2:%3").arg(r.user, r.host).arg(r.port);
}

} // namespace

CorrectionsController::CorrectionsController(QSettings *settings, QObject *parent)
    : QObject(parent), settings_(settings), keychain_(new PasswordKeychain(this)) {
    connect(keychain_, &PasswordKeychain::recalled, this,
            [this](const QString &password, const QString &error) {
                if (error.isEmpty())
                    emit passwordRecalled(password);
                else
                    emit keychainMessage(
                            tr("The password was not read from the keychain: %1").arg(error));
            });
    connect(keychain_, &PasswordKeychain::stored, this, [this](const QString &error) {
        if (!error.isEmpty())
            emit keychainMessage(tr("The password was not kept in the keychain: %1").arg(error));
    });
    connect(&ageSampler_, &QTimer::timeout, this, [this] { monitor_.sampleAge(nowMs()); });
    ageSampler_.start(kAgeSampleMs);
}

CorrectionsController::~CorrectionsController() {
    if (source_) source_->stop();
}

ui::CorrectionsRequest CorrectionsController::remembered() const {
    ui::CorrectionsRequest r;
    if (!settings_) return r;
    settings_->beginGroup(QStringLiteral("corrections"));
    r.kind = settings_->value(QStringLiteral("kind")).toString() == QLatin1String("tcp")
                     ? ui::CorrectionsRequest::Kind::Tcp
                     : ui::CorrectionsRequest::Kind::Ntrip;
    r.host = settings_->value(QStringLiteral("host")).toString();
    r.port = settings_->value(QStringLiteral("port"), 2101).toInt();
    r.mountpoint = settings_->value(QStringLiteral("mountpoint")).toString();
    r.user = settings_->value(QStringLiteral("user")).toString();
    r.ntripVersion = settings_->value(QStringLiteral("ntripVersion"), 2).toInt();
    r.rememberPassword = settings_->value(QStringLiteral("rememberPassword"), false).toBool();
    settings_->endGroup();
    return r;
}

bool CorrectionsController::start(const ui::CorrectionsRequest &r, QString *why) {
    if (!ui::CorrectionsView::validate(r, why)) return false;
    stop();
    if (settings_) { // everything but the password
        settings_->beginGroup(QStringLiteral("corrections"));
        settings_->setValue(QStringLiteral("kind"),
                            r.kind == ui::CorrectionsRequest::Kind::Tcp ? "tcp" : "ntrip");
        settings_->setValue(QStringLiteral("host"), r.host);
        settings_->setValue(QStringLiteral("port"), r.port);
        settings_->setValue(QStringLiteral("mountpoint"), r.mountpoint);
        settings_->setValue(QStringLiteral("user"), r.user);
        settings_->setValue(QStringLiteral("ntripVersion"), r.ntripVersion);
        settings_->setValue(QStringLiteral("rememberPassword"), r.rememberPassword);
        settings_->endGroup();
    }
    // The password: in the keychain when asked (and only there), else removed from it.
    if (r.kind == ui::CorrectionsRequest::Kind::Ntrip && keychainAvailable()) {
        if (r.rememberPassword && !r.password.isEmpty())
            keychain_->store(keychainKey(r), r.password);
        else if (!r.rememberPassword)
            keychain_->forget(keychainKey(r));
    }
    if (r.kind == ui::CorrectionsRequest::Kind::Ntrip) {
        corrections::NtripSettings s;
        s.host = r.host;
        s.port = quint16(r.port);
        s.mountpoint = r.mountpoint;
        s.user = r.user;
        s.password = r.password;
        s.version = r.ntripVersion == 1 ? ntrip::NtripVersion::V1 : ntrip::NtripVersion::V2;
        source_ = std::make_unique<corrections::NtripSource>(s);
    } else {
        source_ = std::make_unique<corrections::TcpCorrectionSource>(r.host, quint16(r.port));
    }
    monitor_.reset();
    ownOutput_ = false;
    if (target_) target_->resetCorrectionFraming();
    connect(source_.get(), &corrections::CorrectionSource::dataReceived, this,
            &CorrectionsController::onData);
    connect(source_.get(), &corrections::CorrectionSource::statusChanged, this,
            [this](const QString &text) { emit statusChanged(text, active()); });
    connect(source_.get(), &corrections::CorrectionSource::stateChanged, this,
            [this] { emit statusChanged(statusText(), active()); });
    source_->start();
    emit statusChanged(statusText(), active());
    return true;
}

void CorrectionsController::stop() {
    if (!source_) return;
    source_->stop();
    source_->disconnect(this);        // nothing more from it reaches the monitor or the receiver
    source_.release()->deleteLater(); // (it may be inside one of its own signals)
    emit statusChanged(tr("Stopped"), false);
}

bool CorrectionsController::keychainAvailable() {
    return PasswordKeychain::available();
}

void CorrectionsController::recallPassword() {
    const ui::CorrectionsRequest r = remembered();
    if (r.rememberPassword && keychainAvailable() && !r.host.isEmpty())
        keychain_->recall(keychainKey(r));
}

bool CorrectionsController::active() const {
    using St = corrections::CorrectionSource::State;
    return source_ && source_->state() != St::Idle && source_->state() != St::Failed;
}

QString CorrectionsController::statusText() const {
    if (ownOutput_ && !active()) return tr("Showing the RTCM 3 the receiver itself sends");
    return source_ ? source_->statusText() : tr("Not started");
}

void CorrectionsController::setTarget(session::ReceiverLink *receiver) {
    target_ = receiver;
    if (!receiver) return;
    connect(receiver, &session::ReceiverLink::connectionStarted, this,
            &CorrectionsController::watch);
    if (receiver->connection()) watch(receiver->connection());
}

void CorrectionsController::watch(link::Connection *connection) {
    connect(connection->stream(), &link::SentenceStream::rtcmFrame, this,
            [this](unsigned, const QByteArray &frame) { onOwnFrame(frame); });
}

void CorrectionsController::onOwnFrame(const QByteArray &frame) {
    if (active()) return; // a source's corrections are what the dock shows then
    if (!ownOutput_) {
        ownOutput_ = true;
        monitor_.reset();
        emit statusChanged(statusText(), false);
    }
    monitor_.feed(std::string_view(frame.constData(), std::size_t(frame.size())), nowMs());
}

void CorrectionsController::setRoverFix(const Epoch &e) {
    const auto position = e.position();
    if (!position) return;
    monitor_.setRoverPosition(*position);
    auto *ntrip = qobject_cast<corrections::NtripSource *>(source_.get());
    if (const auto p = corrections::ggaPositionOf(e); ntrip && p) ntrip->setRoverPosition(*p);
}

void CorrectionsController::onData(const QByteArray &bytes) {
    monitor_.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())), nowMs());
    if (target_) target_->forwardCorrections(bytes);
    emit correctionsReceived(bytes);
}

} // namespace gnss::app
