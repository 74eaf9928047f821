#include "views/receiver_info_view.h"
#include "models/refresh_intervals.h"
#include "style/gnss_style.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"

#include <QCoreApplication>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QRegularExpression>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace gnss::ui {
namespace {

// Flags whose "true" is bad news, and flags whose "false" is bad news (by name; reports are JSON).
bool badWhenTrue(const QString &key) {
    return key.contains("jamming") || key.contains("error") || key.contains("fail") ||
           key.contains("short") || key.contains("overload");
}
bool badWhenFalse(const QString &key) {
    return key.endsWith("_ok") || key.startsWith("ok") || key.contains("_ok_");
}

QString prettyKey(QString k) {
    k.replace('_', ' ');
    if (!k.isEmpty()) k[0] = k[0].toUpper();
    return k;
}

// A report's field name in the user's language (the "Reports" context the catalog in
// translations/ lists), else made readable: "firmware_date" -> "Firmware date".
QString fieldLabel(const QString &key) {
    const QByteArray k = key.toUtf8();
    const QString t = QCoreApplication::translate("Reports", k.constData());
    return t != key ? t : prettyKey(key);
}

// A report's title, translated; a trailing number ("Settings report (PNMRX603) 2") is kept.
QString titleLabel(const QString &title) {
    static const QRegularExpression number(QStringLiteral(" (\\d+)$"));
    const QRegularExpressionMatch m = number.match(title);
    const QString base = m.hasMatch() ? title.left(m.capturedStart()) : title;
    const QString t = QCoreApplication::translate("Reports", base.toUtf8().constData());
    return m.hasMatch() ? t + ' ' + m.captured(1) : t;
}

} // namespace

ReceiverInfoView::ReceiverInfoView(ReceiverStateModel *model, QWidget *parent)
    : QWidget(parent), model_(model) {
    setObjectName("receiverInfo");
    auto *layout = new QVBoxLayout(this);
    identity_ = new QLabel(this);
    identity_->setObjectName("receiverIdentity");
    identity_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(identity_);
    jamming_ = new QLabel(this);
    jamming_->setObjectName("jammingIndicator");
    layout->addWidget(jamming_);
    tree_ = new QTreeWidget(this);
    tree_->setObjectName("receiverReports");
    tree_->setColumnCount(2);
    tree_->setHeaderLabels({tr("Item"), tr("Value")});
    tree_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    layout->addWidget(tree_, 1);
    connect(model_, &ReceiverStateModel::updated, this, [this] { dirty_ = true; });
    startRefreshTimer(timer_, kStatisticsRefreshMs, this, [this] {
        if (dirty_ && isVisible()) refresh();
    });
    refresh();
}

void ReceiverInfoView::addJson(QTreeWidgetItem *parent, const QString &key, const QJsonValue &v) {
    auto *item = new QTreeWidgetItem(parent, {fieldLabel(key)});
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) addJson(item, it.key(), it.value());
        return;
    }
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (int i = 0; i < a.size(); ++i) addJson(item, QString::number(i + 1), a[i]);
        return;
    }
    if (v.isBool()) {
        const bool b = v.toBool();
        item->setText(1, b ? QStringLiteral("✓") : QStringLiteral("✗"));
        const bool bad = (b && badWhenTrue(key)) || (!b && badWhenFalse(key));
        const bool good = (b && badWhenFalse(key)) || (!b && badWhenTrue(key));
        if (bad)
            item->setForeground(1, style::errorColor());
        else if (good)
            item->setForeground(1, style::okColor());
        return;
    }
    if (v.isNull()) {
        item->setText(1, fmt::dash());
        return;
    }
    item->setText(1, v.isDouble() ? QString::number(v.toDouble(), 'g', 12) : v.toString());
    const QString s = v.toString();
    if (s == QLatin1String("ok") || s == QLatin1String("OK"))
        item->setForeground(1, style::okColor());
}

void ReceiverInfoView::refresh() {
    dirty_ = false;
    const ReceiverState &st = model_->state();
    const ReceiverIdentity &id = st.identity;
    if (id.model.empty() && id.vendor.empty()) {
        identity_->setText(tr("Receiver: not identified yet"));
    } else {
        identity_->setText(
                tr("<b>%1 %2</b><br>Firmware: %3%4")
                        .arg(QString::fromStdString(id.vendor), QString::fromStdString(id.model),
                             id.firmware.empty() ? fmt::dash()
                                                 : QString::fromStdString(id.firmware),
                             id.hardware.empty()
                                     ? QString()
                                     : tr("<br>Hardware: %1")
                                               .arg(QString::fromStdString(id.hardware))));
    }
    if (!st.jamming) {
        jamming_->setText(tr("Jamming: not reported"));
        jamming_->setStyleSheet({});
    } else if (*st.jamming) {
        jamming_->setText(tr("Jamming: DETECTED"));
        jamming_->setStyleSheet(QStringLiteral("color: white; background: %1; padding: 2px 6px;")
                                        .arg(style::errorColor().name()));
    } else {
        jamming_->setText(tr("Jamming: none detected"));
        jamming_->setStyleSheet(style::textColorCss(style::okColor()));
    }
    QString key;
    for (const auto &[title, json] : st.reports) key += QString::fromStdString(title + json);
    if (key == shownKey_) return;
    shownKey_ = key;
    // Rebuild, keeping which reports were expanded.
    QSet<QString> expanded;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i)
        if (tree_->topLevelItem(i)->isExpanded()) expanded.insert(tree_->topLevelItem(i)->text(0));
    tree_->clear();
    for (const auto &[title, json] : st.reports) {
        const QString t = titleLabel(QString::fromStdString(title));
        auto *top = new QTreeWidgetItem(tree_, {t});
        const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(json));
        const QJsonObject o = doc.object();
        for (auto it = o.begin(); it != o.end(); ++it) addJson(top, it.key(), it.value());
        top->setExpanded(expanded.isEmpty() || expanded.contains(t));
    }
}

} // namespace gnss::ui
