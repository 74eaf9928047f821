#pragma once
// ReceiversStrip: every receiver of the window in one row, each a chip with its colour, name,
// status (baud found, dialect, rate, errors) and fix; the chip of the receiver the docks show is
// raised. A click selects a receiver; the chip's menu renames, disconnects or closes it. Shown by
// the window while two or more receivers are open.
#include <QColor>
#include <QFrame>
#include <QList>
#include <QToolBar>

class QLabel;

namespace gnss::app {

struct ReceiverEntry {
    QString name, status, fix, tooltip;
    QColor colour, fixColour;
    bool selected = false;
};

class ReceiverChip : public QFrame {
    Q_OBJECT
public:
    explicit ReceiverChip(QWidget *parent = nullptr);
    void setEntry(const ReceiverEntry &e, int number);
    QString name() const;
    QString status() const;
    QString fix() const;

signals:
    void clicked();
    void menuRequested(const QPoint &globalPos);

protected:
    void mousePressEvent(QMouseEvent *e) override;
    void contextMenuEvent(QContextMenuEvent *e) override;

private:
    QLabel *swatch_, *name_, *status_, *fix_;
};

class ReceiversStrip : public QToolBar {
    Q_OBJECT
public:
    explicit ReceiversStrip(QWidget *parent = nullptr);
    // One chip per entry, in order (chip i is Ctrl+i+1).
    void setReceivers(const QList<ReceiverEntry> &entries);
    QList<ReceiverChip *> chips() const { return chips_; }

signals:
    void selectRequested(int index);
    void renameRequested(int index);
    void disconnectRequested(int index);
    void closeRequested(int index);

private:
    QList<ReceiverChip *> chips_;
    QList<QAction *> chipActions_; // deleting one removes its chip
    QAction *add_ = nullptr;
};

} // namespace gnss::app
