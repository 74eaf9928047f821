#include "settings/settings_details.h"

#include "config/setting_values.h"
#include "config/utf8_text.h"
#include "style/gnss_style.h"

#include <QHeaderView>
#include <QTextBrowser>
#include <QTreeWidget>

namespace gnss::ui {

using config::qs;

SettingsDetails::SettingsDetails(QWidget *parent) : QTabWidget(parent) {
    setObjectName("settingDetails");
    help_ = new QTextBrowser(this);
    help_->setObjectName("settingHelp");
    outcomes_ = new QTreeWidget(this);
    outcomes_->setObjectName("settingOutcomes");
    outcomes_->setHeaderLabels({tr("Command / setting"), tr("Outcome"), tr("Detail")});
    outcomes_->setRootIsDecorated(true);
    diff_ = new QTreeWidget(this);
    diff_->setObjectName("profileDiff");
    diff_->setHeaderLabels({tr("Setting"), tr("Profile"), tr("Receiver")});
    diff_->setRootIsDecorated(false);
    addTab(help_, tr("Help"));
    addTab(outcomes_, tr("Outcomes"));
    addTab(diff_, tr("Profile difference"));
}

void SettingsDetails::showHelp(const SettingDef &def, const config::SchemaTexts &texts) {
    QString html = QString("<h3>%1</h3><p><code>%2</code></p><p>%3</p>")
                           .arg(texts(def.label).toHtmlEscaped(), qs(def.key).toHtmlEscaped(),
                                texts(def.help).toHtmlEscaped());
    if (def.min || def.max)
        html += "<p>" +
                tr("Range: %1 to %2 %3")
                        .arg(def.min ? QString::number(*def.min) : "-",
                             def.max ? QString::number(*def.max) : "-", texts(def.unit)) +
                "</p>";
    if (!def.defaultValue.empty())
        html += "<p>" + tr("Default: %1").arg(qs(def.defaultValue).toHtmlEscaped()) + "</p>";
    html += "<p>" + tr("Written with: %1").arg(texts(def.write).toHtmlEscaped()) + "<br>" +
            tr("Read back: %1")
                    .arg(def.access == SettingAccess::WriteOnly
                                 ? tr("cannot be read back (write-only)")
                                 : texts(def.readBack).toHtmlEscaped()) +
            "</p>";
    help_->setHtml(html);
}

void SettingsDetails::showText(const QString &text, bool raise) {
    help_->setPlainText(text);
    if (raise) setCurrentWidget(help_);
}

void SettingsDetails::addReport(const config::OperationReport &r) {
    auto *top = new QTreeWidgetItem(outcomes_,
                                    {r.title, r.ok() ? tr("done") : tr("problems"), r.error});
    for (const auto &c : r.commands) {
        auto *item = new QTreeWidgetItem(top, {c.sentence, link::outcomeName(c.outcome), c.detail});
        for (const QString &reply : c.replies) new QTreeWidgetItem(item, {reply});
    }
    for (const auto &c : r.checks) {
        const bool good = config::isGood(c.verdict);
        auto *item = new QTreeWidgetItem(
                top,
                {QString::fromStdString(c.key + " = " + c.wanted), config::verdictName(c.verdict),
                 c.reported.empty()
                         ? QString()
                         : tr("receiver reports %1").arg(QString::fromStdString(c.reported))});
        if (!good) item->setForeground(1, style::cautionColor());
    }
    top->setExpanded(!r.ok());
    outcomes_->scrollToItem(top);
    outcomes_->header()->resizeSections(QHeaderView::ResizeToContents);
    if (!r.ok()) setCurrentWidget(outcomes_);
}

void SettingsDetails::clearDifference() {
    diff_->clear();
}

void SettingsDetails::addDifference(const QString &key, const QString &profile,
                                    const QString &receiver) {
    auto *item = new QTreeWidgetItem(diff_, {key, profile, receiver});
    item->setData(0, Qt::UserRole, key);
}

void SettingsDetails::showDifference() {
    diff_->header()->resizeSections(QHeaderView::ResizeToContents);
    setCurrentWidget(diff_);
}

} // namespace gnss::ui
