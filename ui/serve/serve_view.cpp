#include "serve/serve_view.h"
#include "widgets/read_only_table.h"

#include <QComboBox>

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QHostAddress>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace gnss::ui {

namespace {

// The address typed, said in words when other machines can reach it.
QString exposure(const QString &address) {
    const QHostAddress a(address);
    if (a.isNull() || a.isLoopback()) return {};
    return ServeView::tr("Listening on %1: other computers can connect.").arg(address);
}

// A server's state, and in red what it exposes (when it does).
void showState(QLabel *label, const QString &text, const QString &warning) {
    label->setTextFormat(warning.isEmpty() ? Qt::PlainText : Qt::RichText);
    label->setText(warning.isEmpty() ? text
                                     : text.toHtmlEscaped() +
                                               QStringLiteral("<br><b style='color:#c62828'>") +
                                               warning.toHtmlEscaped() + QStringLiteral("</b>"));
}

QLabel *stateLabel(const char *name, QWidget *parent) {
    auto *l = new QLabel(parent);
    l->setObjectName(name);
    l->setWordWrap(true);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return l;
}

} // namespace

ServeView::ServeView(QWidget *parent) : QWidget(parent) {
    setObjectName("serveView");
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    outer->addWidget(scroll);
    auto *body = new QWidget(scroll);
    scroll->setWidget(body);
    auto *layout = new QHBoxLayout(body);

    auto *left = new QVBoxLayout;
    auto *caster = new QGroupBox(tr("NTRIP caster"), body);
    auto *form = new QFormLayout(caster);
    auto *where = new QHBoxLayout;
    address_ = new QLineEdit(QStringLiteral("127.0.0.1"), caster);
    address_->setObjectName("serveAddress");
    address_->setToolTip(tr("127.0.0.1: this computer only; 0.0.0.0: every network it is on"));
    port_ = new QSpinBox(caster);
    port_->setObjectName("servePort");
    port_->setRange(0, 65535);
    port_->setValue(2101);
    port_->setToolTip(tr("0: any free port"));
    where->addWidget(address_, 1);
    where->addWidget(port_);
    form->addRow(tr("Listen on:"), where);
    auto *who = new QHBoxLayout;
    user_ = new QLineEdit(caster);
    user_->setObjectName("serveUser");
    user_->setPlaceholderText(tr("no password"));
    password_ = new QLineEdit(caster);
    password_->setObjectName("servePassword");
    password_->setEchoMode(QLineEdit::Password);
    password_->setPlaceholderText(tr("password"));
    who->addWidget(user_);
    who->addWidget(password_);
    form->addRow(tr("User:"), who);
    mounts_ = readOnlyTable(2, "serveMounts", caster);
    mounts_->setHorizontalHeaderLabels({tr("Stream"), tr("Mountpoint")});
    mounts_->setEditTriggers(QAbstractItemView::AllEditTriggers);
    mounts_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    mounts_->setMinimumHeight(70);
    form->addRow(mounts_);
    casterButton_ = new QPushButton(tr("Start caster"), caster);
    casterButton_->setObjectName("serveCasterStartStop");
    form->addRow(casterButton_);
    casterState_ = stateLabel("serveCasterState", caster);
    form->addRow(casterState_);
    left->addWidget(caster);

    auto *raw = new QGroupBox(tr("Share a receiver (raw TCP)"), body);
    auto *rawForm = new QFormLayout(raw);
    rawReceiver_ = new QComboBox(raw);
    rawReceiver_->setObjectName("serveRawReceiver");
    rawForm->addRow(tr("Receiver:"), rawReceiver_);
    auto *rawWhere = new QHBoxLayout;
    rawAddress_ = new QLineEdit(QStringLiteral("127.0.0.1"), raw);
    rawAddress_->setObjectName("serveRawAddress");
    rawPort_ = new QSpinBox(raw);
    rawPort_->setObjectName("serveRawPort");
    rawPort_->setRange(0, 65535);
    rawPort_->setValue(10110); // NMEA over TCP, as chart plotters expect it
    rawWhere->addWidget(rawAddress_, 1);
    rawWhere->addWidget(rawPort_);
    rawForm->addRow(tr("Listen on:"), rawWhere);
    rawButton_ = new QPushButton(tr("Start sharing"), raw);
    rawButton_->setObjectName("serveRawStartStop");
    rawForm->addRow(rawButton_);
    rawState_ = stateLabel("serveRawState", raw);
    rawForm->addRow(rawState_);
    left->addWidget(raw);
    left->addStretch(1);
    layout->addLayout(left, 1);

    auto *clientsBox = new QGroupBox(tr("Clients"), body);
    auto *clientsLayout = new QVBoxLayout(clientsBox);
    clients_ = readOnlyTable(6, "serveClients", clientsBox);
    clients_->setHorizontalHeaderLabels(
            {tr("Server"), tr("Address"), tr("User"), tr("Mountpoint"), tr("Since"), tr("Sent")});
    clients_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    clients_->horizontalHeader()->setStretchLastSection(true);
    clients_->setSelectionBehavior(QAbstractItemView::SelectRows);
    clients_->setSelectionMode(QAbstractItemView::SingleSelection);
    dropClient_ = new QPushButton(tr("Drop client"), clientsBox);
    dropClient_->setObjectName("serveDropClient");
    dropClient_->setToolTip(tr("Disconnect the selected client now (it may connect again)"));
    dropClient_->setEnabled(false);
    auto *clientButtons = new QHBoxLayout;
    clientButtons->addStretch(1);
    clientButtons->addWidget(dropClient_);
    clientsLayout->addLayout(clientButtons); // above the list: in view however tall it is
    clientsLayout->addWidget(clients_);
    layout->addWidget(clientsBox, 1);

    connect(mounts_, &QTableWidget::itemChanged, this, [this] { userEdited_ = true; });
    connect(clients_, &QTableWidget::itemSelectionChanged, this,
            [this] { dropClient_->setEnabled(selectedClient(nullptr, nullptr)); });
    connect(dropClient_, &QPushButton::clicked, this, [this] {
        QString server;
        quint64 id = 0;
        if (selectedClient(&server, &id)) emit dropClientRequested(server, id);
    });
    connect(casterButton_, &QPushButton::clicked, this, [this] {
        if (casterRunning_)
            emit casterStopRequested();
        else
            emit casterStartRequested(casterRequest());
    });
    connect(rawButton_, &QPushButton::clicked, this, [this] {
        if (rawRunning_)
            emit rawStopRequested();
        else
            emit rawStartRequested(rawAddress_->text().trimmed(), rawPort_->value(),
                                   rawReceiver_->currentIndex());
    });
}

void ServeView::setStreams(const QList<ServeStreamChoice> &streams) {
    // What the user ticked and typed stays: by row while the rows are the same streams renamed
    // (a receiver identified), else by label.
    const bool sameRows = mounts_->rowCount() == streams.size();
    QHash<QString, QPair<bool, QString>> byLabel;
    QList<QPair<bool, QString>> byRow;
    for (int r = 0; r < mounts_->rowCount(); ++r) {
        const QPair<bool, QString> v{mounts_->item(r, 0)->checkState() == Qt::Checked,
                                     mounts_->item(r, 1)->text()};
        byLabel[mounts_->item(r, 0)->text()] = v;
        byRow << v;
    }
    const bool edited = userEdited_; // else the suggestions, as they change
    const QSignalBlocker quiet(mounts_);
    mounts_->setRowCount(int(streams.size()));
    for (int r = 0; r < streams.size(); ++r) {
        QPair<bool, QString> v{streams[r].suggested, streams[r].mount};
        if (edited && sameRows)
            v = byRow[r];
        else if (edited && byLabel.contains(streams[r].label))
            v = byLabel[streams[r].label];
        auto *label = new QTableWidgetItem(streams[r].label);
        label->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        label->setCheckState(v.first ? Qt::Checked : Qt::Unchecked);
        mounts_->setItem(r, 0, label);
        auto *mount = new QTableWidgetItem(v.second);
        mount->setFlags(Qt::ItemIsEnabled | Qt::ItemIsEditable | Qt::ItemIsSelectable);
        mounts_->setItem(r, 1, mount);
    }
}

void ServeView::setReceivers(const QStringList &names) {
    const QString current = rawReceiver_->currentText();
    rawReceiver_->clear();
    rawReceiver_->addItems(names);
    if (const int i = rawReceiver_->findText(current); i >= 0) rawReceiver_->setCurrentIndex(i);
}

ServeCasterRequest ServeView::casterRequest() const {
    ServeCasterRequest r;
    r.address = address_->text().trimmed();
    r.port = port_->value();
    r.user = user_->text().trimmed();
    r.password = password_->text();
    for (int i = 0; i < mounts_->rowCount(); ++i)
        if (mounts_->item(i, 0)->checkState() == Qt::Checked)
            r.mounts.append({i, mounts_->item(i, 1)->text().trimmed()});
    return r;
}

void ServeView::setCasterState(bool running, const QString &text) {
    casterRunning_ = running;
    casterButton_->setText(running ? tr("Stop caster") : tr("Start caster"));
    for (QWidget *w : std::initializer_list<QWidget *>{address_, port_, user_, password_, mounts_})
        w->setEnabled(!running);
    showState(casterState_, text, running ? exposure(address_->text().trimmed()) : QString());
}

void ServeView::setRawState(bool running, const QString &text) {
    rawRunning_ = running;
    rawButton_->setText(running ? tr("Stop sharing") : tr("Start sharing"));
    for (QWidget *w : std::initializer_list<QWidget *>{rawReceiver_, rawAddress_, rawPort_})
        w->setEnabled(!running);
    showState(rawState_, text, running ? exposure(rawAddress_->text().trimmed()) : QString());
}

void ServeView::setClients(const QList<QPair<QString, serve::ClientInfo>> &clients) {
    clients_->setRowCount(int(clients.size()));
    const QLocale locale;
    for (int r = 0; r < clients.size(); ++r) {
        const serve::ClientInfo &c = clients[r].second;
        const QStringList cells = {clients[r].first,
                                   QStringLiteral("%1:%2").arg(c.address.toString()).arg(c.port),
                                   c.user,
                                   c.mountpoint,
                                   c.since.toLocalTime().toString(QStringLiteral("HH:mm:ss")),
                                   locale.formattedDataSize(qint64(c.bytesSent))};
        for (int col = 0; col < cells.size(); ++col) {
            QTableWidgetItem *item = clients_->item(r, col);
            if (!item) clients_->setItem(r, col, item = new QTableWidgetItem);
            item->setText(cells[col]);
        }
        clients_->item(r, 0)->setData(Qt::UserRole, QVariant::fromValue(c.id));
    }
    dropClient_->setEnabled(selectedClient(nullptr, nullptr));
}

bool ServeView::selectedClient(QString *server, quint64 *id) const {
    const QList<QTableWidgetItem *> selected = clients_->selectedItems();
    if (selected.isEmpty()) return false;
    const QTableWidgetItem *first = clients_->item(selected.front()->row(), 0);
    if (!first) return false;
    if (server) *server = first->text();
    if (id) *id = first->data(Qt::UserRole).value<quint64>();
    return true;
}

} // namespace gnss::ui
