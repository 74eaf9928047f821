#pragma once
// SettingsToolbar: the settings dock's buttons, wrapping onto a second line in a narrow dock:
// Read, Apply, Revert, Save to flash, Restore defaults, Reset (the dialect's restarts), Presets
// (the dialect's), Profile (import and compare, export). It says what was asked; the view acts.
#include "config/dialect_actions.h"
#include "config/schema_texts.h"

#include <QWidget>

class QPushButton;
class QToolButton;

namespace gnss {
struct Dialect;
}

namespace gnss::ui {

class SettingsToolbar : public QWidget {
    Q_OBJECT
public:
    explicit SettingsToolbar(QWidget *parent = nullptr);

    // The dialect's presets and restarts (`available`: the actions its record has) in the menus.
    void setDialect(const Dialect *d, const config::SchemaTexts &texts,
                    const std::vector<config::Action> &available);

    struct State {
        bool ready = false;   // a dialect, a link that takes commands, nothing running
        bool busy = false;    // an operation running
        bool edited = false;  // values edited, not applied
        bool dialect = false; // a dialect is known
        std::vector<config::Action> actions;
    };
    void setState(const State &s);

signals:
    void readClicked();
    void applyClicked();
    void revertClicked();
    void actionRequested(gnss::config::Action action);
    void presetChosen(const QString &name);
    void importRequested(const QString &path);
    void exportRequested(const QString &path);

private:
    QPushButton *read_, *apply_, *revert_, *save_, *defaults_;
    QToolButton *reset_, *presets_, *profiles_;
};

} // namespace gnss::ui
