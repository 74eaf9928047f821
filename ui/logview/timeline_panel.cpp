#include "logview/timeline_panel.h"

#include "logview/timeline_strip.h"
#include "logview/transport_icons.h"
#include "style/gnss_style.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

namespace gnss::ui {

TimelinePanel::TimelinePanel(LogCursor *cursor, QWidget *parent)
    : QWidget(parent), cursor_(cursor) {
    setObjectName("timelinePanel");
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 0, 2, 0);
    layout->setSpacing(0);
    auto *row = new QHBoxLayout;
    row->setSpacing(2);
    auto button = [&](QAction *a, TransportIcon icon) {
        icons_.push_back({a, icon});
        auto *b = new QToolButton(this);
        b->setDefaultAction(a);
        b->setAutoRaise(true);
        row->addWidget(b);
    };
    button(addAction(tr("Go to the start"), Qt::Key_Home, "logStart", [this] { cursor_->seek(0); }),
           TransportIcon::Start);
    button(addAction(tr("Previous event"), QKeySequence(Qt::CTRL | Qt::Key_Left), "logPrevEvent",
                     [this] { jumpToEvent(false); }),
           TransportIcon::PreviousEvent);
    button(addAction(tr("Step back one epoch"), Qt::Key_Left, "logStepBack", [this] { step(-1); }),
           TransportIcon::StepBack);
    play_ = addAction(tr("Play"), Qt::Key_Space, "logPlay",
                      [this] { emit playRequested(play_->isChecked()); });
    play_->setCheckable(true);
    button(play_, TransportIcon::Play);
    button(addAction(tr("Step forward one epoch"), Qt::Key_Right, "logStepForward",
                     [this] { step(1); }),
           TransportIcon::StepForward);
    button(addAction(tr("Next event"), QKeySequence(Qt::CTRL | Qt::Key_Right), "logNextEvent",
                     [this] { jumpToEvent(true); }),
           TransportIcon::NextEvent);
    button(addAction(tr("Go to the end"), Qt::Key_End, "logEnd",
                     [this] { cursor_->seek(cursor_->epochCount()); }),
           TransportIcon::End);
    speed_ = new QComboBox(this);
    speed_->setObjectName("logSpeed");
    speed_->setToolTip(tr("Playing speed (Ctrl+Up faster, Ctrl+Down slower)"));
    for (double s : speeds())
        speed_->addItem(s > 0 ? tr("%1×").arg(s) : tr("as fast as possible"), s);
    speed_->setCurrentIndex(
            int(std::find(speeds().begin(), speeds().end(), 1.0) - speeds().begin()));
    row->addWidget(speed_);
    addAction(tr("Faster"), QKeySequence(Qt::CTRL | Qt::Key_Up), "logFaster", [this] {
        speed_->setCurrentIndex(std::min(speed_->count() - 1, speed_->currentIndex() + 1));
    });
    addAction(tr("Slower"), QKeySequence(Qt::CTRL | Qt::Key_Down), "logSlower",
              [this] { speed_->setCurrentIndex(std::max(0, speed_->currentIndex() - 1)); });
    connect(speed_, &QComboBox::currentIndexChanged, this, [this] { emit speedChanged(speed()); });
    goTo_ = new QLineEdit(this);
    goTo_->setObjectName("logGoTo");
    goTo_->setPlaceholderText(tr("Go to: 10:42:00, #1200"));
    goTo_->setToolTip(tr("A time of day (10:42:00), a UTC time (2024-03-15T10:42:00Z) or an "
                         "epoch number (#1200), then Enter (Ctrl+G)"));
    goTo_->setClearButtonEnabled(true);
    goTo_->setMaximumWidth(200);
    goTo_->setMinimumWidth(90);
    row->addWidget(goTo_);
    connect(goTo_, &QLineEdit::returnPressed, this, [this] { goTo(goTo_->text()); });
    addAction(tr("Go to a time…"), QKeySequence(Qt::CTRL | Qt::Key_G), "logGoToTime", [this] {
        goTo_->setFocus();
        goTo_->selectAll();
    });
    auto textButton = [&](QAction *a) {
        auto *b = new QToolButton(this);
        b->setDefaultAction(a);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        row->addWidget(b);
    };
    textButton(addAction(tr("Range start"), Qt::Key_BracketLeft, "logRangeStart",
                         [this] { cursor_->setRangeStart(cursor_->current()); }));
    textButton(addAction(tr("Range end"), Qt::Key_BracketRight, "logRangeEnd",
                         [this] { cursor_->setRangeEnd(cursor_->current()); }));
    textButton(addAction(tr("Whole log"), QKeySequence(Qt::CTRL | Qt::Key_Backslash),
                         "logRangeClear", [this] { cursor_->clearRange(); }));
    follow_ = new QCheckBox(tr("Follow"), this);
    follow_->setObjectName("logFollow");
    follow_->setToolTip(tr("Keep reading a log that is still being written; the cursor stays "
                           "at its end"));
    connect(follow_, &QCheckBox::toggled, this, &TimelinePanel::followRequested);
    row->addWidget(follow_);
    // Not one of actions(): it is enabled while indexing, when the transport is not.
    cancel_ = new QAction(tr("Cancel"), this);
    cancel_->setObjectName("logCancelIndexing");
    cancel_->setShortcut(Qt::Key_Escape);
    cancel_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    cancel_->setToolTip(tr("Stop indexing this log (Esc)"));
    cancel_->setEnabled(false);
    connect(cancel_, &QAction::triggered, this, &TimelinePanel::cancelRequested);
    QWidget::addAction(cancel_);
    cancelButton_ = new QToolButton(this);
    cancelButton_->setObjectName("logCancelButton");
    cancelButton_->setDefaultAction(cancel_);
    cancelButton_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    cancelButton_->setVisible(false);
    row->addWidget(cancelButton_);
    message_ = new QLabel(this);
    message_->setObjectName("logMessage");
    message_->setStyleSheet(QStringLiteral("color: %1;").arg(style::errorColor().name()));
    row->addWidget(message_);
    position_ = new QLabel(this);
    position_->setObjectName("logPosition");
    position_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The words may be longer than the room left (Russian, a narrow window): clipped, never
    // widening the window past the screen; the whole text is in the tooltip.
    position_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    position_->setMinimumWidth(120);
    row->addWidget(position_, 1);
    layout->addLayout(row);
    strip_ = new TimelineStrip(cursor_, this);
    strip_->setToolTip(tr("Click or drag to move; Shift+drag selects a range"));
    layout->addWidget(strip_);
    paintIcons();
    connect(cursor_, &LogCursor::moved, this, &TimelinePanel::updateState);
    connect(cursor_, &LogCursor::indexChanged, this, &TimelinePanel::updateState);
    connect(cursor_, &LogCursor::rangeChanged, this, &TimelinePanel::updateState);
    updateState();
}

void TimelinePanel::paintIcons() {
    for (const auto &[action, icon] : icons_)
        action->setIcon(transportIcon(icon, palette().color(QPalette::ButtonText)));
}

void TimelinePanel::changeEvent(QEvent *e) {
    if (e->type() == QEvent::PaletteChange) paintIcons(); // the theme changed
    QWidget::changeEvent(e);
}

const std::vector<double> &TimelinePanel::speeds() {
    static const std::vector<double> s{0.1, 0.25, 0.5, 1, 2, 5, 10, 20, 50, 100, 0};
    return s;
}

double TimelinePanel::speed() const {
    return speed_->currentData().toDouble();
}

void TimelinePanel::setSpeed(double factor) {
    const int i = speed_->findData(factor);
    if (i >= 0) speed_->setCurrentIndex(i);
}

void TimelinePanel::setPlaying(bool playing) {
    play_->setChecked(playing);
    play_->setText(playing ? tr("Pause") : tr("Play"));
    for (auto &[action, icon] : icons_)
        if (action == play_) icon = playing ? TransportIcon::Pause : TransportIcon::Play;
    paintIcons();
}

bool TimelinePanel::playing() const {
    return play_->isChecked();
}
bool TimelinePanel::following() const {
    return follow_->isChecked();
}

QAction *TimelinePanel::addAction(const QString &text, const QKeySequence &key, const char *name,
                                  const std::function<void()> &run) {
    auto *a = new QAction(text, this);
    a->setObjectName(QString::fromLatin1(name));
    a->setShortcut(key);
    a->setShortcutContext(Qt::WindowShortcut);
    a->setToolTip(tr("%1 (%2)").arg(text, key.toString(QKeySequence::NativeText)));
    connect(a, &QAction::triggered, this, run);
    QWidget::addAction(a);
    actions_ << a;
    return a;
}

void TimelinePanel::step(long long delta) {
    if (cursor_->empty()) return;
    const long long k = std::clamp<long long>(static_cast<long long>(cursor_->current()) + delta, 0,
                                              static_cast<long long>(cursor_->epochCount()) - 1);
    cursor_->seek(std::size_t(k));
}

void TimelinePanel::jumpToEvent(bool forward) {
    const logview::LogView *log = cursor_->log();
    if (!log || cursor_->empty()) return;
    const auto k =
            forward ? log->nextEvent(cursor_->current()) : log->previousEvent(cursor_->current());
    if (k)
        cursor_->seek(*k);
    else
        message_->setText(forward ? tr("no later event") : tr("no earlier event"));
}

bool TimelinePanel::goTo(const QString &text) {
    const logview::LogView *log = cursor_->log();
    const auto spec = logview::parseTimeSpec(text.trimmed().toStdString());
    if (!spec) {
        message_->setText(tr("not a time: write 10:42:00, 2024-03-15T10:42:00Z or #1200"));
        return false;
    }
    if (!log) return false;
    const logview::TimeLookup at = logview::lookUpTime(*log, *spec);
    if (at.place != logview::TimePlace::Inside) {
        message_->setText(refusalText(*log, at.place, text.trimmed()));
        return false;
    }
    const std::optional<std::size_t> k = at.epoch;
    message_->clear();
    cursor_->seek(*k, true);
    return true;
}

void TimelinePanel::showMessage(const QString &text) {
    message_->setText(text);
}

QString TimelinePanel::refusalText(const logview::LogView &log, logview::TimePlace place,
                                   const QString &typed) {
    const std::size_t n = log.epochCount();
    const QString first = QString::fromStdString(logview::epochText(log, 0)),
                  last = QString::fromStdString(logview::epochText(log, n ? n - 1 : 0));
    switch (place) {
    case logview::TimePlace::BeforeStart:
        return tr("%1 is before the log's start: it runs from %2 to %3").arg(typed, first, last);
    case logview::TimePlace::AfterEnd:
        if (n == 0) return tr("the log has no epochs");
        return tr("%1 is after the log's end: it runs from %2 to %3").arg(typed, first, last);
    case logview::TimePlace::Untimed:
        return tr("the log's epochs carry no time for %1: write an epoch number (#1200)")
                .arg(typed);
    case logview::TimePlace::Inside: break;
    }
    return {};
}

void TimelinePanel::setIndexing(double fraction, const QString &text) {
    const bool indexing = fraction >= 0;
    cancel_->setEnabled(indexing);
    cancelButton_->setVisible(indexing);
    cancel_->setToolTip(indexing ? tr("Stop indexing: %1 (Esc)").arg(text)
                                 : tr("Stop indexing this log (Esc)"));
}

QString TimelinePanel::positionText() const {
    return position_->text();
}

void TimelinePanel::updateState() {
    const bool open = cursor_->log() && !cursor_->empty();
    for (QAction *a : actions_) a->setEnabled(open);
    speed_->setEnabled(open);
    goTo_->setEnabled(open);
    if (!open) {
        position_->clear();
        return;
    }
    message_->clear();
    const std::size_t k = cursor_->current();
    const auto r = cursor_->log()->epoch(k);
    QString text = tr("#%1 / %2").arg(k).arg(cursor_->epochCount() - 1);
    if (r) {
        text += tr(" · %1 · %2")
                        .arg(QString::fromStdString(logview::formatTime(*r)))
                        .arg(style::fixTypeLabel(r->fixType()));
    }
    if (cursor_->hasRange()) {
        const auto [a, b] = cursor_->selection();
        text += tr(" · range #%1–#%2").arg(a).arg(b);
    }
    position_->setText(text);
    position_->setToolTip(text);
}

} // namespace gnss::ui
