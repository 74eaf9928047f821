#pragma once
// CorrectionsView: the corrections dock. Above, where the corrections come from (an NTRIP
// caster's mountpoint or a base's raw TCP stream) with Start/Stop and the source's status line;
// then what arrives (CorrectionsMonitor: bytes/s, CRC errors, one row per message type with
// count, rate, age and meaning, the base position and the rover-to-base distance) and what was
// forwarded to the receiver; below, what the receiver says of them (its RTK mode, correction age,
// RTCM counts: ReceiverState::rtk), so "corrections arrive" and "the receiver uses them" are
// seen side by side. Refreshes on a 1 Hz timer, never per message.
//
// The view starts nothing itself: it asks (startRequested/stopRequested) and whoever owns the
// source (the application's CorrectionsController) answers with setStatus().
#include "core/wgs84.h"
#include "models/value_format.h"

#include <QString>
#include <QWidget>

#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QChartView;
class QLineSeries;
class QValueAxis;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QTimer;

namespace gnss::corrections {
class CorrectionsMonitor;
struct ForwarderStats;
} // namespace gnss::corrections

namespace gnss::ui {

class ReceiverStateModel;

// What the user asked for. The password is given to the source and never stored by the view.
struct CorrectionsRequest {
    enum class Kind { Ntrip, Tcp };
    Kind kind = Kind::Ntrip;
    QString host;
    int port = 2101;
    QString mountpoint;
    QString user;
    QString password;
    int ntripVersion = 2;
    bool rememberPassword = false; // in the system keychain, never in the settings
    bool operator==(const CorrectionsRequest &) const = default;
};

class CorrectionsView : public QWidget {
    Q_OBJECT
public:
    // `forwarded` returns the forwarding counts, or null when nothing is forwarded (no receiver).
    CorrectionsView(const corrections::CorrectionsMonitor &monitor, ReceiverStateModel *receiver,
                    std::function<const corrections::ForwarderStats *()> forwarded,
                    QWidget *parent = nullptr);

    // The form's fields (remembered values given back; the password stays empty).
    void setRequest(const CorrectionsRequest &r);
    CorrectionsRequest request() const;
    // Whether the request is complete; `why` in words when not.
    static bool validate(const CorrectionsRequest &r, QString *why);

    // The source's state: `active` while started (Start becomes Stop).
    void setStatus(const QString &text, bool active);
    // The monitor shows the receiver's own RTCM output (a base), not a source's: the distance is
    // then from the receiver's own fix.
    void setOwnOutput(bool own) { ownOutput_ = own; }
    // Where a base of the window was set to send station `id` from (its receiver's name and the
    // point): the 1005/1006 position is shown against it. Empty: no such base.
    struct SetBase {
        QString receiver;
        wgs84::Ecef position;
    };
    using SetBaseLookup = std::function<std::optional<SetBase>(unsigned station)>;
    void setSetBaseLookup(SetBaseLookup lookup) { setBase_ = std::move(lookup); }
    // Shown instead of the status when a request was refused before anything was started.
    void showError(const QString &text);

    // Whether the password can be kept (a keychain is there): the option is shown only then.
    void setKeychainAvailable(bool available);
    // A password recalled from the keychain.
    void setPassword(const QString &password);

    // Rows in the message-type table (tests).
    int messageTypeRows() const;

public slots:
    void refresh();
    // Coordinates in the user's format, heights and distances in their units.
    void setDisplayPrefs(const DisplayPrefs &prefs) {
        prefs_ = prefs;
        refresh();
    }

signals:
    void startRequested(const gnss::ui::CorrectionsRequest &request);
    void stopRequested();

protected:
    void changeEvent(QEvent *e) override;

private:
    DisplayPrefs prefs_;
    void onStartStop();
    void updateKind();

    const corrections::CorrectionsMonitor &monitor_;
    ReceiverStateModel *receiver_;
    std::function<const corrections::ForwarderStats *()> forwarded_;
    SetBaseLookup setBase_;
    bool active_ = false;
    bool ownOutput_ = false;
    bool keychain_ = false;

    QComboBox *kind_, *version_;
    QLineEdit *host_, *mount_, *user_, *password_;
    QSpinBox *port_;
    QCheckBox *remember_;
    QPushButton *startStop_;
    QLabel *status_, *stream_, *base_, *forwarding_, *receiverSide_;
    QLabel *mountLabel_, *userLabel_, *passwordLabel_, *versionLabel_;
    QTableWidget *types_;
    QChartView *ageChart_;
    QLineSeries *ageSeries_;
    QValueAxis *ageX_, *ageY_;
    QTimer *timer_;
};

} // namespace gnss::ui
