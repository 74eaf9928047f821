#include "settings/settings_toolbar.h"

#include "config/utf8_text.h"
#include "core/dialect.h"
#include "widgets/flow_layout.h"

#include <QFileDialog>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>

namespace gnss::ui {

using config::qs;

SettingsToolbar::SettingsToolbar(QWidget *parent) : QWidget(parent) {
    auto *bar = new FlowLayout(this);
    bar->setContentsMargins(0, 0, 0, 0);
    read_ = new QPushButton(tr("Read"), this);
    read_->setObjectName("settingsRead");
    read_->setToolTip(tr("Read every setting the receiver reports"));
    apply_ = new QPushButton(tr("Apply"), this);
    apply_->setObjectName("settingsApply");
    apply_->setToolTip(tr("Send the edited values (only what differs), then read them back"));
    revert_ = new QPushButton(tr("Revert"), this);
    revert_->setObjectName("settingsRevert");
    revert_->setToolTip(tr("Forget the edits: show the receiver's values again"));
    save_ = new QPushButton(tr("Save to flash"), this);
    defaults_ = new QPushButton(tr("Restore defaults"), this);
    reset_ = new QToolButton(this);
    reset_->setObjectName("settingsReset");
    reset_->setText(tr("Reset"));
    reset_->setPopupMode(QToolButton::InstantPopup);
    presets_ = new QToolButton(this);
    presets_->setObjectName("settingsPresets");
    presets_->setText(tr("Presets"));
    presets_->setPopupMode(QToolButton::InstantPopup);
    profiles_ = new QToolButton(this);
    profiles_->setText(tr("Profile"));
    profiles_->setPopupMode(QToolButton::InstantPopup);
    auto *profileMenu = new QMenu(profiles_);
    profileMenu->addAction(tr("Import and compare..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import settings profile"), {},
                                                          tr("Settings profiles (*.json)"));
        if (!path.isEmpty()) emit importRequested(path);
    });
    profileMenu->addAction(tr("Export..."), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export settings profile"), {},
                                                          tr("Settings profiles (*.json)"));
        if (!path.isEmpty()) emit exportRequested(path);
    });
    profiles_->setMenu(profileMenu);
    for (QWidget *w : std::initializer_list<QWidget *>{read_, apply_, revert_, save_, defaults_,
                                                       reset_, presets_, profiles_})
        bar->addWidget(w);
    connect(read_, &QPushButton::clicked, this, &SettingsToolbar::readClicked);
    connect(apply_, &QPushButton::clicked, this, &SettingsToolbar::applyClicked);
    connect(revert_, &QPushButton::clicked, this, &SettingsToolbar::revertClicked);
    connect(save_, &QPushButton::clicked, this,
            [this] { emit actionRequested(config::Action::SaveToFlash); });
    connect(defaults_, &QPushButton::clicked, this,
            [this] { emit actionRequested(config::Action::RestoreDefaults); });
}

void SettingsToolbar::setDialect(const Dialect *d, const config::SchemaTexts &texts,
                                 const std::vector<config::Action> &available) {
    // Presets of this dialect.
    auto *menu = new QMenu(presets_);
    if (d)
        for (const Preset &p : d->presets) {
            QAction *a = menu->addAction(texts(p.name));
            a->setToolTip(texts(p.description));
            const QString name = qs(p.name);
            connect(a, &QAction::triggered, this, [this, name] { emit presetChosen(name); });
        }
    delete presets_->menu();
    presets_->setMenu(menu);
    presets_->setEnabled(!menu->isEmpty());
    // Restarts the dialect offers.
    auto *resets = new QMenu(reset_);
    if (d)
        for (config::Action a : available) {
            if (a == config::Action::SaveToFlash || a == config::Action::RestoreDefaults) continue;
            const ActionDef *def = findAction(*d, a);
            resets->addAction(texts(def->label), this, [this, a] { emit actionRequested(a); });
        }
    delete reset_->menu();
    reset_->setMenu(resets);
}

void SettingsToolbar::setState(const State &s) {
    auto has = [&](config::Action a) {
        return std::find(s.actions.begin(), s.actions.end(), a) != s.actions.end();
    };
    read_->setEnabled(s.ready);
    apply_->setEnabled(s.ready && s.edited);
    revert_->setEnabled(!s.busy && s.edited);
    save_->setEnabled(s.ready && has(config::Action::SaveToFlash));
    save_->setToolTip(has(config::Action::SaveToFlash)
                              ? tr("Write the settings in force to the receiver's flash")
                              : tr("This receiver has no command to save its settings"));
    defaults_->setEnabled(s.ready && has(config::Action::RestoreDefaults));
    reset_->setEnabled(s.ready && reset_->menu() && !reset_->menu()->isEmpty());
    profiles_->setEnabled(s.dialect && !s.busy);
}

} // namespace gnss::ui
