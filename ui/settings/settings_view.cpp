#include "settings/settings_view.h"

#include "config/utf8_text.h"
#include "style/gnss_style.h"

#include "config/presets.h"
#include "config/setting_values.h"
#include "settings/setting_editors.h"
#include "settings/settings_details.h"
#include "settings/settings_toolbar.h"
#include "widgets/flow_layout.h"

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStackedWidget>
#include <QStyle>
#include <QTabWidget>
#include <QTextBrowser>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace gnss::ui {

namespace {

using config::qs;

// Edited values: Okabe-Ito orange, the palette of the views' colours (ui/style).
const QColor kEdited(0xE6, 0x9F, 0x00);

// Shows a setting's help when its editor takes focus.
class FocusHelp : public QObject {
public:
    FocusHelp(QObject *parent, std::function<void()> f) : QObject(parent), f_(std::move(f)) {}
    bool eventFilter(QObject *, QEvent *e) override {
        if (e->type() == QEvent::FocusIn || e->type() == QEvent::Enter) f_();
        return false;
    }

private:
    std::function<void()> f_;
};

} // namespace

SettingsView::SettingsView(config::SettingsEngine *engine, QWidget *parent)
    : QWidget(parent), engine_(engine) {
    confirm_ = [this](const QString &title, const QString &text) {
        return QMessageBox::question(this, title, text) == QMessageBox::Yes;
    };
    auto *top = new QVBoxLayout(this);
    top->setContentsMargins(4, 4, 4, 4);
    toolbar_ = new SettingsToolbar(this);
    top->addWidget(toolbar_);
    // Why the buttons are off when the link takes no commands (a receiver that gpsd holds, a
    // replayed log): said above the form rather than leaving disabled buttons unexplained.
    sendNote_ = new QLabel(this);
    sendNote_->setObjectName("settingsSendNote");
    sendNote_->setWordWrap(true);
    sendNote_->setVisible(false);
    top->addWidget(sendNote_);

    createFormArea(top);
    createFoot(top);
    wireToolbar();
    followEngine();
    rebuild();
}

void SettingsView::createFormArea(QVBoxLayout *top) {
    // Group choice: a list beside the form when the dock is wide, a combo box above it when it
    // is narrow (the form always keeps the width it needs); a filter across every group.
    auto *chooser = new QHBoxLayout;
    groupCombo_ = new QComboBox(this);
    groupCombo_->setObjectName("settingGroupCombo");
    groupCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    filter_ = new QLineEdit(this);
    filter_->setObjectName("settingFilter");
    filter_->setPlaceholderText(tr("Find a setting"));
    filter_->setClearButtonEnabled(true);
    chooser->addWidget(groupCombo_);
    chooser->addWidget(filter_, 1);
    top->addLayout(chooser);

    split_ = new QSplitter(Qt::Vertical, this);
    split_->setChildrenCollapsible(true);
    auto *formArea = new QWidget(split_);
    auto *formRow = new QHBoxLayout(formArea);
    formRow->setContentsMargins(0, 0, 0, 0);
    groups_ = new QListWidget(formArea);
    groups_->setObjectName("settingGroups");
    groups_->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Expanding);
    pages_ = new QStackedWidget(formArea);
    pages_->setObjectName("settingPages");
    formRow->addWidget(groups_);
    formRow->addWidget(pages_, 1);
    // Help, outcomes and a profile's difference share one pane below the form.
    details_ = new SettingsDetails(split_);
    split_->addWidget(formArea);
    split_->addWidget(details_);
    split_->setStretchFactor(0, 3);
    split_->setStretchFactor(1, 1);
    split_->setCollapsible(0, false);
    top->addWidget(split_, 1);
    connect(groups_, &QListWidget::currentRowChanged, this, &SettingsView::showGroup);
    connect(groupCombo_, &QComboBox::currentIndexChanged, this, &SettingsView::showGroup);
    connect(filter_, &QLineEdit::textChanged, this, &SettingsView::applyFilter);
}

void SettingsView::createFoot(QVBoxLayout *top) {
    auto *foot = new QHBoxLayout;
    status_ = new QLabel(this);
    status_->setObjectName("settingsStatus");
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    progress_ = new QProgressBar(this);
    progress_->setMaximumWidth(200);
    progress_->setVisible(false);
    cancel_ = new QPushButton(tr("Cancel"), this);
    foot->addWidget(status_, 1);
    foot->addWidget(progress_);
    foot->addWidget(cancel_);
    top->addLayout(foot);
}

void SettingsView::wireToolbar() {
    connect(toolbar_, &SettingsToolbar::readClicked, this, &SettingsView::readAll);
    connect(toolbar_, &SettingsToolbar::applyClicked, this, &SettingsView::applyEdits);
    connect(toolbar_, &SettingsToolbar::revertClicked, this, &SettingsView::revert);
    connect(toolbar_, &SettingsToolbar::actionRequested, this, &SettingsView::runAction);
    connect(toolbar_, &SettingsToolbar::presetChosen, this, &SettingsView::loadPreset);
    connect(toolbar_, &SettingsToolbar::importRequested, this, [this](const QString &path) {
        QString error;
        if (!importProfile(path, &error)) status(tr("%1 was not imported: %2").arg(path, error));
    });
    connect(toolbar_, &SettingsToolbar::exportRequested, this, [this](const QString &path) {
        QString error;
        if (!exportProfile(path, &error)) status(error);
    });
    connect(cancel_, &QPushButton::clicked, engine_, &config::SettingsEngine::cancel);
}

void SettingsView::followEngine() {
    connect(engine_, &config::SettingsEngine::dialectChanged, this, [this](const Dialect *d) {
        rebuild();
        if (d && engine_->canSend()) readAll(); // on connect: what the receiver is set to now
    });
    connect(engine_, &config::SettingsEngine::queueChanged, this, [this] {
        // The link came (after the dialect was known) or came back: read what is set now.
        if (engine_->dialect() && engine_->canSend() && !engine_->isBusy()) readAll();
        updateButtons();
    });
    connect(engine_, &config::SettingsEngine::valuesChanged, this, &SettingsView::refreshValues);
    connect(engine_, &config::SettingsEngine::busyChanged, this, &SettingsView::updateButtons);
    connect(engine_, &config::SettingsEngine::progress, this,
            [this](int done, int total, const QString &step) {
                progress_->setRange(0, std::max(total, 1));
                progress_->setValue(done);
                progress_->setFormat(QString("%1 %p%").arg(step));
            });
    connect(engine_, &config::SettingsEngine::finished, this, &SettingsView::showReport);
}

void SettingsView::showGroup(int index) {
    if (index < 0 || index >= pages_->count()) return;
    pages_->setCurrentIndex(index);
    // Keep both choosers on the same group (only one of them is shown at a time).
    const QSignalBlocker a(groups_), b(groupCombo_);
    groups_->setCurrentRow(index);
    groupCombo_->setCurrentIndex(index);
}

void SettingsView::resizeEvent(QResizeEvent *e) {
    QWidget::resizeEvent(e);
    if (!splitSized_ && split_->height() > 200) {
        // The form gets most of the height; help and outcomes a strip that can be dragged open.
        const int h = split_->height();
        split_->setSizes({h - h / 4, h / 4});
        splitSized_ = true;
    }
    updateGroupChooser();
    updateRowWrapping();
}

bool SettingsView::eventFilter(QObject *watched, QEvent *e) {
    if (e->type() == QEvent::Resize) updateRowWrapping();
    return QWidget::eventFilter(watched, e);
}

void SettingsView::updateGroupChooser() {
    // The list is shown only when the form keeps at least kFormMinWidth beside it.
    constexpr int kFormMinWidth = 460;
    const bool wide = groups_->count() > 0 && width() >= groups_->width() + kFormMinWidth;
    groups_->setVisible(wide);
    groupCombo_->setVisible(!wide && groupCombo_->count() > 0);
}

void SettingsView::updateRowWrapping() {
    // One arrangement per page, so its rows read alike, the widest that fits the view:
    //   labels beside editors, receiver values beside editors;
    //   labels above editors, receiver values beside editors;
    //   labels above editors, receiver values below editors.
    for (int page = 0; page < pages_->count(); ++page) {
        auto *scroll = qobject_cast<QScrollArea *>(pages_->widget(page));
        auto *form = scroll ? qobject_cast<QFormLayout *>(scroll->widget()->layout()) : nullptr;
        if (!form) continue;
        int labels = 0, beside = 0, stacked = 0;
        for (int row = 0; row < form->rowCount(); ++row) {
            if (QLayoutItem *l = form->itemAt(row, QFormLayout::LabelRole))
                labels = std::max(labels, l->sizeHint().width());
            QLayoutItem *f = form->itemAt(row, QFormLayout::FieldRole);
            auto *box =
                    f && f->widget() ? qobject_cast<QBoxLayout *>(f->widget()->layout()) : nullptr;
            if (!box || box->count() < 2) continue;
            const int editor = box->itemAt(0)->minimumSize().width();
            const int value = box->itemAt(1)->sizeHint().width();
            const bool coordinates = f->widget()->property("stacked").toBool();
            beside = std::max(beside, coordinates ? std::max(editor, value)
                                                  : editor + box->spacing() + value);
            stacked = std::max(stacked, std::max(editor, value));
        }
        const QMargins m = form->contentsMargins();
        const int available = scroll->viewport()->width() - m.left() - m.right();
        const bool labelsBeside = labels + form->horizontalSpacing() + beside <= available;
        const bool valuesBeside = labelsBeside || beside <= available;
        const auto policy = labelsBeside ? QFormLayout::DontWrapRows : QFormLayout::WrapAllRows;
        if (form->rowWrapPolicy() != policy) form->setRowWrapPolicy(policy);
        for (int row = 0; row < form->rowCount(); ++row) {
            QLayoutItem *f = form->itemAt(row, QFormLayout::FieldRole);
            auto *box =
                    f && f->widget() ? qobject_cast<QBoxLayout *>(f->widget()->layout()) : nullptr;
            if (!box || f->widget()->property("stacked").toBool()) continue;
            const auto dir = valuesBeside ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
            if (box->direction() != dir) box->setDirection(dir);
        }
    }
}

void SettingsView::applyFilter(const QString &text) {
    const QString needle = text.trimmed();
    int firstMatch = -1;
    for (int page = 0; page < pages_->count(); ++page) {
        auto *scroll = qobject_cast<QScrollArea *>(pages_->widget(page));
        auto *form = scroll ? qobject_cast<QFormLayout *>(scroll->widget()->layout()) : nullptr;
        if (!form) continue;
        int shown = 0;
        for (int row = 0; row < form->rowCount(); ++row) {
            auto *label = qobject_cast<QLabel *>(
                    form->itemAt(row, QFormLayout::LabelRole)
                            ? form->itemAt(row, QFormLayout::LabelRole)->widget()
                            : nullptr);
            const QString key = label ? label->property("settingKey").toString() : QString();
            const bool match = needle.isEmpty() || !label ||
                               label->text().contains(needle, Qt::CaseInsensitive) ||
                               key.contains(needle, Qt::CaseInsensitive);
            form->setRowVisible(row, match);
            shown += match ? 1 : 0;
        }
        const bool any = shown > 0;
        if (QListWidgetItem *item = groups_->item(page)) item->setHidden(!any);
        if (any && firstMatch < 0) firstMatch = page;
    }
    if (!needle.isEmpty() && firstMatch >= 0 && groups_->item(pages_->currentIndex()) &&
        groups_->item(pages_->currentIndex())->isHidden())
        showGroup(firstMatch);
    if (!needle.isEmpty() && firstMatch < 0) status(tr("No setting matches \"%1\".").arg(needle));
}

void SettingsView::rebuild() {
    while (pages_->count()) {
        QWidget *w = pages_->widget(0);
        pages_->removeWidget(w);
        w->deleteLater();
    }
    {
        const QSignalBlocker a(groups_), b(groupCombo_);
        groups_->clear();
        groupCombo_->clear();
    }
    editors_.clear();
    receiverLabels_.clear();
    rowLabels_.clear();
    edits_.clear();
    details_->clearDifference();
    const Dialect *d = engine_->dialect();
    texts_ = d ? config::SchemaTexts(d->id) : config::SchemaTexts();
    if (!d || d->settings.empty()) {
        details_->showText(d ? tr("The %1 receiver has no settings this program knows.")
                                           .arg(qs(d->displayName))
                             : tr("Connect to a receiver: its settings appear here."),
                           true);
        toolbar_->setDialect(d, texts_, {});
        updateGroupChooser();
        updateButtons();
        return;
    }
    std::map<QString, QFormLayout *> forms;
    for (const SettingDef &def : d->settings) {
        if (config::isAction(def)) continue; // restarts etc. are the buttons above
        const QString group = qs(def.group);
        QFormLayout *&form = forms[group];
        if (!form) {
            auto *scroll = new QScrollArea(pages_);
            scroll->setObjectName("page:" + group); // the schema's name, whatever the language
            scroll->setWidgetResizable(true);
            scroll->setFrameShape(QFrame::NoFrame);
            scroll->viewport()->installEventFilter(this); // rows re-wrap when it resizes
            auto *page = new QWidget(scroll);
            form = new QFormLayout(page);
            // Labels beside their editors while both fit, above them when they do not
            // (updateRowWrapping): every label whole and every editor at its full size.
            form->setRowWrapPolicy(QFormLayout::DontWrapRows);
            form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
            form->setLabelAlignment(Qt::AlignLeft | Qt::AlignVCenter);
            scroll->setWidget(page);
            pages_->addWidget(scroll);
            groups_->addItem(texts_(def.group));
            groupCombo_->addItem(texts_(def.group));
        }
        addRow(form, def);
    }
    // The group list is as wide as its longest name (and a scroll bar), no wider.
    groups_->setFixedWidth(groups_->sizeHintForColumn(0) + 2 * groups_->frameWidth() +
                           groups_->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 8);
    // BASEXYZ ⇄ BASEBLH: each coordinate editor fills itself from the other form.
    std::vector<CoordinateEditor *> coords;
    for (auto &[key, e] : editors_)
        if (auto *c = qobject_cast<CoordinateEditor *>(e)) coords.push_back(c);
    for (CoordinateEditor *c : coords) {
        CoordinateEditor *other = nullptr;
        for (CoordinateEditor *o : coords)
            if (o != c && o->kind() != c->kind()) other = o;
        c->convertButton()->setVisible(other != nullptr);
        if (!other) continue;
        c->convertButton()->setText(tr("From %1").arg(qs(other->def().key).section('.', -1)));
        c->convertButton()->setToolTip(
                tr("Convert the %1 position to this form (WGS-84)").arg(qs(other->def().key)));
        connect(c->convertButton(), &QPushButton::clicked, c,
                [c, other] { c->setGeodetic(other->geodetic()); });
    }
    toolbar_->setDialect(d, texts_, engine_->availableActions());
    showGroup(0);
    details_->showText(tr("%1: select a setting to see its help.").arg(qs(d->displayName)));
    applyFilter(filter_->text());
    updateGroupChooser();
    updateRowWrapping();
    refreshValues();
    updateButtons();
}

void SettingsView::addRow(QFormLayout *form, const SettingDef &def) {
    // An editor never gets less than it asks for (see SettingEditor): the row wraps, or the
    // page scrolls, instead.
    SettingEditor *e = makeSettingEditor(def, texts_, nullptr);
    const std::string key(def.key);
    auto *label =
            new QLabel(texts_(def.label) + (def.unit.empty() ? "" : " (" + texts_(def.unit) + ")"));
    label->setObjectName("label:" + qs(def.key));
    label->setProperty("settingKey", qs(def.key));
    label->setToolTip(texts_(def.help));
    label->setBuddy(e->input());
    auto *receiver = new QLabel;
    receiver->setObjectName("receiver:" + qs(def.key));
    receiver->setTextInteractionFlags(Qt::TextSelectableByMouse);
    receiver->setForegroundRole(QPalette::PlaceholderText);
    // The receiver's value beside the editor; below it for the wide coordinate editors.
    auto *cell = new QWidget;
    const bool coordinates = qobject_cast<CoordinateEditor *>(e) != nullptr;
    cell->setProperty("stacked", coordinates); // always the value below (updateRowWrapping)
    auto *box =
            new QBoxLayout(coordinates ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight, cell);
    box->setContentsMargins(0, 0, 0, 0);
    box->setSpacing(8);
    box->addWidget(e);
    box->addWidget(receiver);
    box->addStretch(1);
    form->addRow(label, cell);
    if (def.access == SettingAccess::ReadOnly) e->setEnabled(false);
    editors_[key] = e;
    receiverLabels_[key] = receiver;
    rowLabels_[key] = label;
    connect(e, &SettingEditor::edited, this, [this, e] { onEdited(e); });
    auto *filter = new FocusHelp(e, [this, e] { showHelp(e->def()); });
    e->input()->installEventFilter(filter);
    label->installEventFilter(new FocusHelp(label, [this, e] { showHelp(e->def()); }));
}

void SettingsView::refreshValues() {
    for (auto &[key, e] : editors_) {
        receiverLabels_[key]->setText(tr("receiver: %1").arg(engine_->displayValue(key)));
        if (edits_.count(key)) {
            // Still an edit only while it differs from the receiver.
            const auto rv = engine_->receiverValue(key);
            if (rv && config::sameValue(e->def(), edits_[key].toStdString(), *rv))
                setEdited(key, false);
            continue;
        }
        if (const auto rv = engine_->receiverValue(key)) e->setValue(QString::fromStdString(*rv));
    }
}

void SettingsView::setEdited(const std::string &key, bool edited) {
    SettingEditor *e = editors_.at(key);
    if (edited)
        edits_[key] = e->value();
    else
        edits_.erase(key);
    e->setProperty("edited", edited);
    QLabel *label = rowLabels_.at(key);
    QFont f = label->font();
    f.setBold(edited);
    label->setFont(f);
    label->setStyleSheet(edited ? QString("color: %1;").arg(kEdited.name()) : QString());
    e->input()->setStyleSheet(
            edited ? QString("background-color: %1;").arg(kEdited.lighter(170).name()) : QString());
    updateButtons();
}

void SettingsView::onEdited(SettingEditor *e) {
    const std::string key(e->def().key);
    const auto rv = engine_->receiverValue(key);
    const bool differs = !rv || !config::sameValue(e->def(), e->value().toStdString(), *rv);
    setEdited(key, differs);
    showHelp(e->def());
}

void SettingsView::showHelp(const SettingDef &def) {
    details_->showHelp(def, texts_);
}

std::vector<KeyValue> SettingsView::edits() const {
    std::vector<KeyValue> out;
    // Schema order.
    if (const Dialect *d = engine_->dialect())
        for (const auto &def : d->settings)
            if (auto it = edits_.find(std::string(def.key)); it != edits_.end())
                out.push_back({it->first, it->second.toStdString()});
    return out;
}

SettingEditor *SettingsView::editor(const std::string &key) const {
    auto it = editors_.find(key);
    return it == editors_.end() ? nullptr : it->second;
}

QStringList SettingsView::pageNames() const {
    QStringList out;
    for (int i = 0; i < groups_->count(); ++i) out << groups_->item(i)->text();
    return out;
}

void SettingsView::readAll() {
    status(tr("Reading the receiver's settings..."));
    engine_->read();
}

void SettingsView::applyEdits() {
    const auto values = edits();
    if (values.empty()) {
        status(tr("Nothing to apply: no value was changed."));
        return;
    }
    status(tr("Applying %n setting(s)...", nullptr, static_cast<int>(values.size())));
    engine_->apply(values);
}

void SettingsView::revert() {
    const auto keys = edits_;
    for (const auto &[key, value] : keys) {
        setEdited(key, false);
        SettingEditor *e = editors_.at(key);
        if (const auto rv = engine_->receiverValue(key))
            e->setValue(QString::fromStdString(*rv));
        else
            e->setValue(qs(e->def().defaultValue));
    }
    details_->clearDifference();
    status(tr("Edits reverted."));
}

void SettingsView::runAction(config::Action action) {
    const Dialect *d = engine_->dialect();
    const ActionDef *def = d ? findAction(*d, action) : nullptr;
    if (!def) {
        status(tr("This receiver has no such command."));
        return;
    }
    const QString label = texts_(def->label);
    if (!confirm_(label,
                  tr("%1 on the %2?\n\n%3").arg(label, qs(d->displayName), texts_(def->effect))))
        return;
    status(tr("%1...").arg(label));
    engine_->runAction(action);
}

void SettingsView::loadPreset(const QString &name) {
    const Dialect *d = engine_->dialect();
    if (!d) return;
    for (const Preset &p : d->presets) {
        if (qs(p.name) != name) continue;
        for (const auto &kv : config::presetValues(p)) {
            SettingEditor *e = editor(kv.key);
            if (!e) continue;
            e->setValue(QString::fromStdString(kv.value));
            onEdited(e);
        }
        status(tr("Preset \"%1\" loaded: %n setting(s) differ from the receiver. Apply sends "
                  "them.",
                  nullptr, static_cast<int>(edits_.size()))
                       .arg(texts_(p.name)));
        return;
    }
}

bool SettingsView::importProfile(const QString &path, QString *error) {
    config::Profile p;
    if (!config::loadProfile(path, p, error, engine_->dialect())) return false;
    // A profile of another model is not loaded as edits, so Apply cannot send it.
    if (const QString why =
                config::profileMismatch(p, engine_->dialect(), engine_->identity().model);
        !why.isEmpty()) {
        if (error) *error = why;
        return false;
    }
    // What differs is what Apply would send: a value its command would not take is refused
    // here, before an editor could clamp it to its range and send another value.
    const auto entries = engine_->diff(p);
    std::vector<KeyValue> changes;
    for (const auto &e : entries) changes.push_back({e.key, e.profileValue});
    if (const QStringList refused = engine_->dialect()
                                            ? config::refusedValues(*engine_->dialect(), changes)
                                            : QStringList();
        !refused.isEmpty()) {
        if (error) *error = refused.join(QStringLiteral("; "));
        return false;
    }
    details_->clearDifference();
    for (const auto &e : entries) {
        details_->addDifference(QString::fromStdString(e.key),
                                QString::fromStdString(e.profileValue),
                                e.receiverKnown ? QString::fromStdString(e.receiverValue)
                                                : engine_->displayValue(e.key));
        if (SettingEditor *ed = editor(e.key)) {
            ed->setValue(QString::fromStdString(e.profileValue));
            onEdited(ed);
        }
    }
    details_->showDifference();
    status(entries.empty()
                   ? tr("The receiver already has every setting of %1.").arg(path)
                   : tr("%n setting(s) of the profile differ from the receiver (model %1, firmware "
                        "%2); they are loaded as edits: Apply sends them.",
                        nullptr, static_cast<int>(entries.size()))
                             .arg(QString::fromStdString(p.model),
                                  QString::fromStdString(p.firmware)));
    return true;
}

bool SettingsView::exportProfile(const QString &path, QString *error) {
    if (!engine_->dialect()) {
        if (error) *error = tr("Not connected to a receiver.");
        return false;
    }
    const config::Profile p = engine_->exportProfile();
    if (!config::saveProfile(path, p, error)) return false;
    status(tr("%n setting(s) exported to %1.", nullptr, static_cast<int>(p.values.size()))
                   .arg(path));
    return true;
}

void SettingsView::showReport(const config::OperationReport &r) {
    details_->addReport(r);
    // A value that took is no longer an edit; one that did not stays highlighted.
    for (const auto &c : r.checks)
        if (config::isGood(c.verdict) && editors_.count(c.key)) setEdited(c.key, false);
    QString text;
    if (!r.error.isEmpty())
        text = tr("%1: %2").arg(r.title, r.error);
    else if (r.cancelled)
        text = tr("%1: cancelled.").arg(r.title);
    else if (r.nothingToDo)
        text = tr("Nothing to send: the receiver already has these values.");
    else if (r.failedCommands() || r.failedChecks())
        text = tr("%1: %2 command(s) failed, %3 setting(s) did not take; see Outcomes.")
                       .arg(r.title)
                       .arg(r.failedCommands())
                       .arg(r.failedChecks());
    else
        text = tr("%1: done (%n command(s)).", nullptr, static_cast<int>(r.commands.size()))
                       .arg(r.title);
    if (r.readBackOnReturn)
        text += QLatin1Char(' ') +
                tr("The link was lost: these settings are read back when it returns.");
    status(text);
    refreshValues();
}

void SettingsView::updateButtons() {
    const bool busy = engine_->isBusy();
    SettingsToolbar::State state;
    state.busy = busy;
    state.dialect = engine_->dialect() != nullptr;
    state.ready = state.dialect && engine_->canSend() && !busy;
    state.edited = !edits_.empty();
    state.actions = engine_->availableActions();
    toolbar_->setState(state);
    const QString refusal = engine_->sendRefusal();
    sendNote_->setText(
            refusal.isEmpty()
                    ? QString()
                    : tr("%1. Settings can be neither read nor changed from here.").arg(refusal));
    sendNote_->setVisible(!refusal.isEmpty());
    cancel_->setVisible(busy);
    progress_->setVisible(busy);
}

void SettingsView::status(const QString &text) {
    status_->setText(text);
}

} // namespace gnss::ui
