#include "views/corrections_view.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"
#include "style/gnss_style.h"
#include "views/chart_palette.h"
#include "widgets/fitted_columns.h"
#include "widgets/read_only_table.h"

#include "corrections/correction_forwarder.h"
#include "corrections/corrections_monitor.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <cmath>

namespace gnss::ui {

namespace {

constexpr int kRefreshMs = 1000; // the counts and ages change once a second at most

QLabel *wrappingLabel(const char *objectName) {
    auto *l = new QLabel;
    l->setObjectName(QLatin1String(objectName));
    l->setWordWrap(true);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return l;
}

// The monitor's clock: the milliseconds CorrectionsController feeds it with (wall clock).
std::int64_t nowMs() {
    return QDateTime::currentMSecsSinceEpoch();
}

QString rtkModeText(std::optional<char> mode) {
    if (!mode) return fmt::dash();
    switch (*mode) {
    case 'R': return CorrectionsView::tr("RTK fixed");
    case 'F': return CorrectionsView::tr("RTK float");
    case 'D': return CorrectionsView::tr("differential");
    case 'A': return CorrectionsView::tr("autonomous");
    case 'N': return CorrectionsView::tr("no fix");
    default: return QString(QLatin1Char(*mode));
    }
}

} // namespace

CorrectionsView::CorrectionsView(const corrections::CorrectionsMonitor &monitor,
                                 ReceiverStateModel *receiver,
                                 std::function<const corrections::ForwarderStats *()> forwarded,
                                 QWidget *parent)
    : QWidget(parent), monitor_(monitor), receiver_(receiver), forwarded_(std::move(forwarded)),
      timer_(new QTimer(this)) {
    // In a scroll area: the dock never asks the window for more height than a laptop has.
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("correctionsScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);
    auto *content = new QWidget(scroll);
    scroll->setWidget(content);
    auto *layout = new QVBoxLayout(content);

    // Where from.
    auto *sourceBox = new QGroupBox(tr("Source"), content);
    auto *form = new QFormLayout(sourceBox);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    kind_ = new QComboBox;
    kind_->setObjectName(QStringLiteral("correctionsKind"));
    kind_->addItem(tr("NTRIP caster"));
    kind_->addItem(tr("TCP stream (a base's raw RTCM)"));
    form->addRow(tr("Type"), kind_);
    auto *hostRow = new QHBoxLayout;
    host_ = new QLineEdit;
    host_->setObjectName(QStringLiteral("correctionsHost"));
    host_->setPlaceholderText(tr("caster.example.org"));
    port_ = new QSpinBox;
    port_->setObjectName(QStringLiteral("correctionsPort"));
    port_->setRange(1, 65535);
    port_->setValue(2101);
    hostRow->addWidget(host_, 1);
    hostRow->addWidget(port_);
    form->addRow(tr("Host and port"), hostRow);
    mount_ = new QLineEdit;
    mount_->setObjectName(QStringLiteral("correctionsMount"));
    mountLabel_ = new QLabel(tr("Mountpoint"));
    form->addRow(mountLabel_, mount_);
    user_ = new QLineEdit;
    user_->setObjectName(QStringLiteral("correctionsUser"));
    userLabel_ = new QLabel(tr("User"));
    form->addRow(userLabel_, user_);
    password_ = new QLineEdit;
    password_->setObjectName(QStringLiteral("correctionsPassword"));
    password_->setEchoMode(QLineEdit::Password);
    password_->setPlaceholderText(tr("not stored"));
    passwordLabel_ = new QLabel(tr("Password"));
    form->addRow(passwordLabel_, password_);
    remember_ = new QCheckBox(tr("Remember the password in the system keychain"));
    remember_->setObjectName(QStringLiteral("correctionsRememberPassword"));
    remember_->setVisible(false);
    form->addRow(QString(), remember_);
    version_ = new QComboBox;
    version_->setObjectName(QStringLiteral("correctionsVersion"));
    version_->addItem(tr("NTRIP 2 (HTTP/1.1)"), 2);
    version_->addItem(tr("NTRIP 1"), 1);
    versionLabel_ = new QLabel(tr("Protocol"));
    form->addRow(versionLabel_, version_);
    startStop_ = new QPushButton(tr("Start"));
    startStop_->setObjectName(QStringLiteral("correctionsStartStop"));
    form->addRow(startStop_);
    status_ = wrappingLabel("correctionsStatus");
    status_->setText(tr("Not started"));
    form->addRow(status_);
    layout->addWidget(sourceBox);

    // What arrives.
    auto *streamBox = new QGroupBox(tr("Received"), content);
    auto *streamLayout = new QVBoxLayout(streamBox);
    stream_ = wrappingLabel("correctionsStream");
    streamLayout->addWidget(stream_);
    types_ = readOnlyTable(5, "correctionsTypes", content);
    types_->setMinimumHeight(types_->verticalHeader()->defaultSectionSize() * 4);
    types_->setHorizontalHeaderLabels(
            {tr("Message"), tr("Count"), tr("Rate, /s"), tr("Age, s"), tr("Meaning")});
    types_->setSelectionMode(QAbstractItemView::NoSelection);
    // Rewritten cell by cell at every refresh: measured when types come or go and once a second.
    new FittedColumns(types_, types_->horizontalHeader());
    streamLayout->addWidget(types_, 1);
    // The correction age over the last ten minutes (the monitor samples it once a second).
    ageSeries_ = new QLineSeries;
    auto *chart = new QChart;
    chart->addSeries(ageSeries_);
    chart->legend()->hide();
    chart->setTitle(tr("Correction age, s (last 10 min)"));
    chart->setMargins(QMargins(2, 2, 2, 2));
    ageX_ = new QValueAxis;
    ageX_->setRange(-600, 0);
    ageX_->setLabelFormat(QStringLiteral("%d"));
    ageY_ = new QValueAxis;
    ageY_->setRange(0, 5);
    ageY_->setLabelFormat(QStringLiteral("%d")); // whole seconds
    ageY_->setTruncateLabels(false);             // Qt 6.4 elides them to "…" in a low chart
    chart->addAxis(ageX_, Qt::AlignBottom);
    chart->addAxis(ageY_, Qt::AlignLeft);
    ageSeries_->attachAxis(ageX_);
    ageSeries_->attachAxis(ageY_);
    ageChart_ = new QChartView(chart, content);
    ageChart_->setObjectName(QStringLiteral("correctionsAgeChart"));
    ageChart_->setRenderHint(QPainter::Antialiasing);
    ageChart_->setMinimumHeight(140);
    style::applyChartPalette(chart, ageChart_, {ageX_, ageY_}, palette());
    streamLayout->addWidget(ageChart_);
    base_ = wrappingLabel("correctionsBase");
    streamLayout->addWidget(base_);
    forwarding_ = wrappingLabel("correctionsForwarding");
    streamLayout->addWidget(forwarding_);
    layout->addWidget(streamBox, 1);

    // What the receiver says.
    auto *receiverBox = new QGroupBox(tr("Receiver"), content);
    auto *receiverLayout = new QVBoxLayout(receiverBox);
    receiverSide_ = wrappingLabel("correctionsReceiver");
    receiverLayout->addWidget(receiverSide_);
    layout->addWidget(receiverBox);

    connect(kind_, &QComboBox::currentIndexChanged, this, &CorrectionsView::updateKind);
    connect(remember_, &QCheckBox::toggled, this, &CorrectionsView::updateKind);
    connect(startStop_, &QPushButton::clicked, this, &CorrectionsView::onStartStop);
    connect(timer_, &QTimer::timeout, this, &CorrectionsView::refresh);
    timer_->start(kRefreshMs);
    updateKind();
    refresh();
}

void CorrectionsView::updateKind() {
    const bool ntrip = kind_->currentIndex() == 0;
    for (QWidget *w :
         {static_cast<QWidget *>(mount_), static_cast<QWidget *>(user_),
          static_cast<QWidget *>(password_), static_cast<QWidget *>(version_),
          static_cast<QWidget *>(mountLabel_), static_cast<QWidget *>(userLabel_),
          static_cast<QWidget *>(passwordLabel_), static_cast<QWidget *>(versionLabel_)})
        w->setVisible(ntrip);
    remember_->setVisible(ntrip && keychain_);
    password_->setPlaceholderText(keychain_ && remember_->isChecked() ? tr("kept in the keychain")
                                                                      : tr("not stored"));
}

void CorrectionsView::setRequest(const CorrectionsRequest &r) {
    kind_->setCurrentIndex(r.kind == CorrectionsRequest::Kind::Ntrip ? 0 : 1);
    host_->setText(r.host);
    port_->setValue(r.port);
    mount_->setText(r.mountpoint);
    user_->setText(r.user);
    remember_->setChecked(r.rememberPassword);
    version_->setCurrentIndex(r.ntripVersion == 1 ? 1 : 0);
    updateKind();
}

CorrectionsRequest CorrectionsView::request() const {
    CorrectionsRequest r;
    r.kind = kind_->currentIndex() == 0 ? CorrectionsRequest::Kind::Ntrip
                                        : CorrectionsRequest::Kind::Tcp;
    r.host = host_->text().trimmed();
    r.port = port_->value();
    r.mountpoint = mount_->text().trimmed();
    if (r.mountpoint.startsWith(QLatin1Char('/'))) r.mountpoint.remove(0, 1);
    r.user = user_->text().trimmed();
    r.password = password_->text();
    r.rememberPassword =
            keychain_ && r.kind == CorrectionsRequest::Kind::Ntrip && remember_->isChecked();
    r.ntripVersion = version_->currentData().toInt();
    return r;
}

bool CorrectionsView::validate(const CorrectionsRequest &r, QString *why) {
    auto fail = [why](const QString &text) {
        if (why) *why = text;
        return false;
    };
    if (r.host.isEmpty()) return fail(tr("Give the host of the corrections."));
    // "user:password@caster": not repeated (the password would show), nor remembered.
    if (r.host.contains(QLatin1Char('@')))
        return fail(tr("Give only the host name or address here: the user name and the password "
                       "have their own fields."));
    if (r.host.contains(QLatin1Char(' ')) || r.host.contains(QLatin1Char('/')))
        return fail(tr("'%1' is not a host name or address.").arg(r.host));
    if (r.port < 1 || r.port > 65535) return fail(tr("The port is 1 to 65535."));
    if (r.kind == CorrectionsRequest::Kind::Ntrip) {
        if (r.mountpoint.isEmpty()) return fail(tr("Give the mountpoint."));
        if (r.mountpoint.contains(QLatin1Char(' ')) || r.mountpoint.contains(QLatin1Char('/')))
            return fail(tr("'%1' is not a mountpoint name.").arg(r.mountpoint));
        if (!r.password.isEmpty() && r.user.isEmpty())
            return fail(tr("A password was given without a user name."));
    }
    return true;
}

void CorrectionsView::onStartStop() {
    if (active_) {
        emit stopRequested();
        return;
    }
    const CorrectionsRequest r = request();
    QString why;
    if (!validate(r, &why)) {
        showError(why);
        return;
    }
    emit startRequested(r);
}

void CorrectionsView::setStatus(const QString &text, bool active) {
    active_ = active;
    startStop_->setText(active ? tr("Stop") : tr("Start"));
    status_->setText(text);
    status_->setStyleSheet({});
    for (QWidget *w : {static_cast<QWidget *>(kind_), static_cast<QWidget *>(host_),
                       static_cast<QWidget *>(port_), static_cast<QWidget *>(mount_),
                       static_cast<QWidget *>(user_), static_cast<QWidget *>(password_),
                       static_cast<QWidget *>(version_), static_cast<QWidget *>(remember_)})
        w->setEnabled(!active);
}

void CorrectionsView::showError(const QString &text) {
    status_->setText(text);
    status_->setStyleSheet(QStringLiteral("color: palette(highlight);"));
}

void CorrectionsView::changeEvent(QEvent *e) {
    if (e->type() == QEvent::PaletteChange)
        style::applyChartPalette(ageChart_->chart(), ageChart_, {ageX_, ageY_}, palette());
    QWidget::changeEvent(e);
}

void CorrectionsView::setKeychainAvailable(bool available) {
    keychain_ = available;
    updateKind();
}

void CorrectionsView::setPassword(const QString &password) {
    password_->setText(password);
}

int CorrectionsView::messageTypeRows() const {
    return types_->rowCount();
}

void CorrectionsView::refresh() {
    const std::int64_t now = nowMs();
    const auto types = monitor_.messageTypes(now);
    types_->setRowCount(int(types.size()));
    for (int row = 0; row < int(types.size()); ++row) {
        const corrections::MessageTypeStats &t = types[std::size_t(row)];
        const QString cells[] = {
                QString::number(t.number),
                QString::number(t.count),
                QString::number(t.ratePerSecond, 'f', 1),
                QString::number(double(t.ageMs) / 1000.0, 'f', 1),
                QCoreApplication::translate("RtcmMessage", t.meaning.c_str()),
        };
        for (int c = 0; c < 5; ++c) {
            auto *item = types_->item(row, c);
            if (!item) {
                item = new QTableWidgetItem;
                if (c < 4) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                types_->setItem(row, c, item);
            }
            item->setText(cells[c]);
        }
    }
    QList<QPointF> points;
    double highest = 5;
    for (const corrections::AgeSample &s : monitor_.ageHistory()) {
        if (!s.ageMs) continue;
        const double age = double(*s.ageMs) / 1000.0;
        points.append({double(s.atMs - now) / 1000.0, age});
        highest = std::max(highest, age * 1.2);
    }
    ageSeries_->replace(points);
    ageY_->setRange(0, highest);
    ageY_->applyNiceNumbers(); // whole steps: 0, 1, 2 ... rather than 1.25
    const auto age = monitor_.correctionAgeMs(now);
    stream_->setText(
            tr("%1 B/s, %2 messages, %3 CRC errors, %4 bytes not RTCM; correction age %5")
                    .arg(QString::number(monitor_.bytesPerSecond(now), 'f', 0))
                    .arg(monitor_.messages())
                    .arg(monitor_.crcErrors())
                    .arg(monitor_.bytesSkipped())
                    .arg(age ? tr("%1 s").arg(double(*age) / 1000.0, 0, 'f', 1) : fmt::dash()));
    if (const auto &b = monitor_.basePosition()) {
        const UnitSystem u = prefs_.units;
        // ECEF stays in metres: it is the frame's own unit, as RTCM sends it.
        QString where =
                b->geodetic ? tr("%1, %2, %3")
                                      .arg(fmt::latitude(b->geodetic->latDeg, prefs_.coordinates),
                                           fmt::longitude(b->geodetic->lonDeg, prefs_.coordinates),
                                           fmt::length(b->geodetic->height, 2, u))
                            : tr("ECEF %1, %2, %3 m")
                                      .arg(b->ecef.x, 0, 'f', 3)
                                      .arg(b->ecef.y, 0, 'f', 3)
                                      .arg(b->ecef.z, 0, 'f', 3);
        const auto baseline = monitor_.baselineMetres();
        base_->setText((ownOutput_ ? tr("Base station %1 (%2): %3; from the receiver's own fix %4")
                                   : tr("Base station %1 (%2): %3; distance to the rover %4"))
                               .arg(b->station)
                               .arg(b->message)
                               .arg(where, fmt::distance(baseline, 3, u)));
        // Against the position a base of the window was set to (the same station id).
        if (const auto set = setBase_ ? setBase_(b->station) : std::nullopt) {
            const double d = std::hypot(b->ecef.x - set->position.x, b->ecef.y - set->position.y,
                                        b->ecef.z - set->position.z);
            base_->setText(
                    base_->text() + QLatin1Char('\n') +
                    tr("%1 from the position set on %2").arg(fmt::length(d, 3, u), set->receiver));
        }
    } else {
        base_->setText(tr("Base station: not yet received (1005/1006)"));
    }
    if (const corrections::ForwarderStats *f = forwarded_ ? forwarded_() : nullptr)
        forwarding_->setText(tr("Forwarded to the receiver: %1 frames (%2 bytes); dropped %3")
                                     .arg(f->framesForwarded)
                                     .arg(f->bytesForwarded)
                                     .arg(f->framesDropped));
    else
        forwarding_->setText(tr("Not forwarded: no receiver connected"));
    if (!receiver_) return;
    const RtkState &rtk = receiver_->state().rtk;
    const Epoch &e = receiver_->state().epoch;
    const std::optional<double> receiverAge = rtk.correctionAge ? rtk.correctionAge : e.dgpsAge;
    QString text = tr("Fix: %1; RTK mode %2; correction age %3")
                           .arg(style::fixTypeLabel(e.fix), rtkModeText(rtk.mode),
                                fmt::number(receiverAge, 1, tr("s")));
    if (rtk.rtcmTotal)
        text += tr("; RTCM messages received %1, bad %2")
                        .arg(*rtk.rtcmTotal)
                        .arg(rtk.rtcmErrors.value_or(0));
    receiverSide_->setText(text);
}

} // namespace gnss::ui
