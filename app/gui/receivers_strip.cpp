#include "gui/receivers_strip.h"

#include "style/gnss_style.h"

#include <QContextMenuEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QVBoxLayout>

namespace gnss::app {

ReceiverChip::ReceiverChip(QWidget *parent) : QFrame(parent) {
    setObjectName("receiverChip");
    setFrameShape(QFrame::StyledPanel);
    setCursor(Qt::PointingHandCursor);
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(6, 2, 6, 2);
    row->setSpacing(6);
    swatch_ = new QLabel(this);
    swatch_->setFixedSize(10, 28);
    row->addWidget(swatch_);
    auto *text = new QVBoxLayout;
    text->setSpacing(0);
    name_ = new QLabel(this);
    name_->setObjectName("receiverName");
    QFont bold = name_->font();
    bold.setBold(true);
    name_->setFont(bold);
    status_ = new QLabel(this);
    status_->setObjectName("receiverStatus");
    QFont small = status_->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    status_->setFont(small);
    text->addWidget(name_);
    text->addWidget(status_);
    row->addLayout(text);
    fix_ = new QLabel(this);
    fix_->setObjectName("receiverFix");
    fix_->setAlignment(Qt::AlignCenter);
    row->addWidget(fix_);
}

void ReceiverChip::setEntry(const ReceiverEntry &e, int number) {
    swatch_->setStyleSheet(
            QStringLiteral("background: %1; border-radius: 2px;").arg(e.colour.name()));
    name_->setText(tr("%1. %2").arg(number).arg(e.name));
    status_->setText(e.status);
    fix_->setText(e.fix);
    fix_->setStyleSheet(style::badgeCss(e.fixColour, 4, "1px 6px"));
    setToolTip(e.tooltip);
    // The receiver the docks show: raised, with its colour around it.
    setFrameShadow(e.selected ? QFrame::Raised : QFrame::Plain);
    setStyleSheet(
            e.selected
                    ? QStringLiteral("#receiverChip { border: 2px solid %1; }").arg(e.colour.name())
                    : QStringLiteral("#receiverChip { border: 1px solid palette(mid); }"));
    setProperty("selected", e.selected);
}

QString ReceiverChip::name() const {
    return name_->text();
}

QString ReceiverChip::status() const {
    return status_->text();
}

QString ReceiverChip::fix() const {
    return fix_->text();
}

void ReceiverChip::mousePressEvent(QMouseEvent *e) {
    QFrame::mousePressEvent(e);
    emit clicked();
}

void ReceiverChip::contextMenuEvent(QContextMenuEvent *e) {
    emit menuRequested(e->globalPos());
}

ReceiversStrip::ReceiversStrip(QWidget *parent) : QToolBar(tr("Receivers"), parent) {
    setObjectName("receiversBar");
    setMovable(false);
    // Where the chips end (Add receiver is in the connection bar and the Receiver menu).
    add_ = addSeparator();
}

void ReceiversStrip::setReceivers(const QList<ReceiverEntry> &entries) {
    while (chips_.size() > entries.size()) {
        chips_.removeLast();
        delete chipActions_.takeLast();
    }
    while (chips_.size() < entries.size()) {
        auto *chip = new ReceiverChip(this);
        const int index = int(chips_.size());
        chipActions_ << insertWidget(add_, chip);
        connect(chip, &ReceiverChip::clicked, this, [this, index] { emit selectRequested(index); });
        connect(chip, &ReceiverChip::menuRequested, this, [this, index](const QPoint &at) {
            QMenu menu(this);
            menu.addAction(tr("Show in the docks"), this,
                           [this, index] { emit selectRequested(index); });
            menu.addAction(tr("Rename..."), this, [this, index] { emit renameRequested(index); });
            menu.addAction(tr("Disconnect"), this,
                           [this, index] { emit disconnectRequested(index); });
            menu.addAction(tr("Close receiver"), this,
                           [this, index] { emit closeRequested(index); });
            menu.exec(at);
        });
        chips_ << chip;
    }
    for (int i = 0; i < entries.size(); ++i) chips_[i]->setEntry(entries[i], i + 1);
}

} // namespace gnss::app
