#pragma once
// SettingsView: the settings dock, its form pages and what ties them to the engine; the buttons
// are SettingsToolbar, the pane below the form SettingsDetails. Generated from the connected
// dialect's schema: one page per
// group (a list beside the form when the dock is wide, a combo box above it when narrow), the
// right editor per setting at its full size with the receiver's value beside it, labels beside
// or above their editors as the width allows, help as tooltips and in a pane below the form. Edited
// values are highlighted against the receiver's. Read / Apply / Revert / Save to flash / Restore
// defaults / Reset (confirmed), presets, profile import (with its difference) and export; each
// command's outcome and each setting's verification listed. Knows no vendor: the schema, the engine
// and the presets table say everything.
#include "config/schema_texts.h"
#include "config/settings_engine.h"

#include <QWidget>

#include <functional>
#include <map>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSplitter;
class QListWidget;
class QProgressBar;
class QPushButton;
class QStackedWidget;
class QVBoxLayout;

namespace gnss::ui {

class SettingEditor;
class SettingsDetails;
class SettingsToolbar;

class SettingsView : public QWidget {
    Q_OBJECT
public:
    explicit SettingsView(config::SettingsEngine *engine, QWidget *parent = nullptr);

    // Asked before save / restore / reset; the default asks with a message box. Tests replace it.
    using Confirm = std::function<bool(const QString &title, const QString &text)>;
    void setConfirm(Confirm c) { confirm_ = std::move(c); }

    // The values the user changed, not yet applied (key → value).
    std::vector<KeyValue> edits() const;
    bool isEdited(const std::string &key) const { return edits_.count(key) != 0; }
    SettingEditor *editor(const std::string &key) const;
    QStringList pageNames() const;

    // Actions (the buttons call these).
    void readAll();
    void applyEdits();
    void revert();
    void runAction(config::Action action);
    void loadPreset(const QString &name);
    bool importProfile(const QString &path, QString *error = nullptr); // edits = its difference
    bool exportProfile(const QString &path, QString *error = nullptr);

protected:
    void resizeEvent(QResizeEvent *e) override;
    bool eventFilter(QObject *watched, QEvent *e) override;

private:
    // The constructor's parts: group choice, pages and details; status, progress and cancel;
    // the toolbar's requests; the engine's news.
    void createFormArea(QVBoxLayout *top);
    void createFoot(QVBoxLayout *top);
    void wireToolbar();
    void followEngine();
    void rebuild();
    void addRow(QFormLayout *form, const SettingDef &def);
    void showGroup(int index);
    void updateGroupChooser();
    void updateRowWrapping();
    void applyFilter(const QString &text);
    void refreshValues();
    void setEdited(const std::string &key, bool edited);
    void onEdited(SettingEditor *e);
    void showHelp(const SettingDef &def);
    void showReport(const config::OperationReport &r);
    void updateButtons();
    void status(const QString &text);

    config::SettingsEngine *engine_;
    config::SchemaTexts texts_; // the connected dialect's texts, translated
    Confirm confirm_;
    QListWidget *groups_;
    QComboBox *groupCombo_;
    QLineEdit *filter_;
    QSplitter *split_;
    bool splitSized_ = false;
    QStackedWidget *pages_;
    SettingsToolbar *toolbar_;
    SettingsDetails *details_;
    QLabel *status_;
    QLabel *sendNote_;
    QProgressBar *progress_;
    QPushButton *cancel_;
    std::map<std::string, SettingEditor *> editors_;
    std::map<std::string, QLabel *> receiverLabels_, rowLabels_;
    std::map<std::string, QString> edits_;
};

} // namespace gnss::ui
