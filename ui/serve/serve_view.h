#pragma once
// ServeView: the Serve dock. The window's streams served to other programs (protocol/serve):
//   - an NTRIP caster (revisions 1 and 2): where it listens (127.0.0.1 unless the user types
//     another address, said in red when it is not loopback), an optional user and password, and
//     a mountpoint per stream ticked: a receiver's own RTCM (a base), or the corrections a
//     receiver is fed (re-broadcast);
//   - a raw TCP port that passes one receiver's bytes to other programs (read-only);
//   - the clients of both: address, user, mountpoint, connected since, bytes sent; the one
//     selected can be dropped.
// It knows no session: the controller gives it the streams and the clients and does what it asks.
#include "serve/stream_clients.h"

#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;
class QComboBox;
class QSpinBox;
class QTableWidget;

namespace gnss::ui {

struct ServeStreamChoice {
    QString label;          // "RTCM of NV08C-RTK /dev/ttyUSB0"
    QString mount;          // the mountpoint offered
    bool suggested = false; // ticked at first (a receiver that sends RTCM)
};

struct ServeCasterRequest {
    QString address = QStringLiteral("127.0.0.1");
    int port = 2101;
    QString user, password;
    QList<QPair<int, QString>> mounts; // stream index, mountpoint
};

class ServeView : public QWidget {
    Q_OBJECT
public:
    explicit ServeView(QWidget *parent = nullptr);

    // The streams the window can serve, in the controller's order (kept ticks by label).
    void setStreams(const QList<ServeStreamChoice> &streams);
    // The receivers whose bytes the raw port can pass on.
    void setReceivers(const QStringList &names);
    void setCasterState(bool running, const QString &text);
    void setRawState(bool running, const QString &text);
    // Every client of both servers ("NTRIP" or "raw" in the first column).
    void setClients(const QList<QPair<QString, serve::ClientInfo>> &clients);
    // The client in the selected row (its server as setClients named it); false when none.
    bool selectedClient(QString *server, quint64 *id) const;

    ServeCasterRequest casterRequest() const;

signals:
    void casterStartRequested(const gnss::ui::ServeCasterRequest &request);
    void casterStopRequested();
    void rawStartRequested(const QString &address, int port, int receiver);
    void rawStopRequested();
    // "Drop client": the server's name as setClients gave it, and the client's id.
    void dropClientRequested(const QString &server, quint64 id);

private:
    QLineEdit *address_;
    QSpinBox *port_;
    QLineEdit *user_, *password_;
    QTableWidget *mounts_;
    QPushButton *casterButton_;
    QLabel *casterState_;
    QComboBox *rawReceiver_;
    QLineEdit *rawAddress_;
    QSpinBox *rawPort_;
    QPushButton *rawButton_;
    QLabel *rawState_;
    QTableWidget *clients_;
    QPushButton *dropClient_;
    bool casterRunning_ = false, rawRunning_ = false;
    bool userEdited_ = false; // the user ticked or renamed a stream: no more suggestions
};

} // namespace gnss::ui
