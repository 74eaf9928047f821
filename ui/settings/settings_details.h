#pragma once
// SettingsDetails: the pane below the settings form, one tab each: a setting's help, the
// outcome of every operation (each command, its replies, each setting's verdict), and an
// imported profile's difference from the receiver.
#include "config/schema_texts.h"
#include "config/settings_engine.h"

#include <QTabWidget>

class QTextBrowser;
class QTreeWidget;

namespace gnss::ui {

class SettingsDetails : public QTabWidget {
    Q_OBJECT
public:
    explicit SettingsDetails(QWidget *parent = nullptr);

    // A setting's help: label, key, help text, range, default, how it is written and read back.
    void showHelp(const SettingDef &def, const config::SchemaTexts &texts);
    void showText(const QString &text, bool raise = false);
    // An operation's outcome, added below the earlier ones (in front when it had problems).
    void addReport(const config::OperationReport &r);
    // A profile's difference: cleared, then a row per setting (shown in front by showDifference).
    void clearDifference();
    void addDifference(const QString &key, const QString &profile, const QString &receiver);
    void showDifference();

private:
    QTextBrowser *help_;
    QTreeWidget *outcomes_;
    QTreeWidget *diff_;
};

} // namespace gnss::ui
