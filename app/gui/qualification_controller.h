#pragma once
// QualificationController: what the Qualification dock asks, done on the window's receivers.
// A campaign (qualify::TtffCampaign) per receiver asked for — the selected one, or every one at
// once with the same restarts written at the same moment (each waits for the others before it
// restarts) — each on its own link, its runs kept here (a receiver closed
// mid-campaign keeps the runs it had). Each receiver's positions are kept for the accuracy
// against the reference (live, shown once a second). The report is made from what is kept:
// identity, settings as the settings engine read them back, conditions, runs, accuracy.
#include "compare/accuracy.h"
#include "models/value_format.h"
#include "qualify/qualification_view.h"
#include "qualify/report.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>

namespace gnss::ui {
class ReceiverSession;
}

namespace gnss::app {

class QualificationController : public QObject {
    Q_OBJECT
public:
    struct Receivers {
        std::function<QList<ui::ReceiverSession *>()> all;
        std::function<ui::ReceiverSession *()> selected;
    };
    QualificationController(Receivers receivers, QObject *parent = nullptr);

    // The dock's view (made again when the dock is): the controller fills it and follows it.
    void attach(ui::QualificationView *view);
    void setDisplayPrefs(const ui::DisplayPrefs &prefs);
    // A new receiver (its positions are kept from now on).
    void follow(ui::ReceiverSession *s);

    bool running() const;
    // Starts what `r` asks; false with the reason shown (and nothing sent) when it cannot.
    bool start(const ui::QualificationRequest &r);
    void cancel();
    // The report input of the last campaign (empty receivers: none ran).
    qualify::ReportInput reportInput() const;
    // Writes the report (PDF or HTML by the extension) and its CSV and JSON; the files written.
    QStringList writeReport(const QString &path, QString *error) const;

signals:
    void runningChanged(bool running);
    void message(const QString &text); // for the status bar

private:
    struct Entry {
        QPointer<ui::ReceiverSession> session;
        QPointer<qualify::TtffCampaign> campaign;
        qualify::ReportReceiver data;
        int total = 0;
        bool done = false;
    };
    void refresh();
    void refreshAccuracy();
    void go();
    void finishedOne();
    qualify::ReportReceiver identityOf(ui::ReceiverSession *s) const;

    Receivers receivers_;
    QPointer<ui::QualificationView> view_;
    ui::DisplayPrefs prefs_;
    ui::QualificationRequest request_;
    std::vector<Entry> entries_;
    QDateTime started_, ended_;
    QElapsedTimer clock_;
    QTimer tick_;
    QHash<const ui::ReceiverSession *, compare::PositionSet> positions_;
};

} // namespace gnss::app
