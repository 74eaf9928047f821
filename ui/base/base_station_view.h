#pragma once
// BaseStationView: the Base station dock. For a receiver whose dialect can be a base (its schema's
// base-station roles, protocol/base), everything `gnss-cli base` does, on the session's settings
// engine and its epochs:
//   - the base as the receiver has it (role, position, station, RTCM interval, ports) and the
//     distance from its own fix, in red past its threshold (it sends no corrections then);
//   - where the base is: a survey-in by the workbench (a time or an accuracy, progress, the
//     running mean, σ east/north/up, the mean's accuracy and a convergence plot), a survey-in by
//     the receiver (its averaging time, followed), or a known position typed as geodetic (degrees,
//     DM, DMS; ellipsoidal or sea-level height) or ECEF, or picked from the site list; an antenna
//     height added;
//   - station, RTCM interval and the port that carries the RTCM; Set base applies them and reads
//     them back, each setting's verdict listed; saved to flash when asked.
// A survey's result, or the base's position, can be kept as a site.
#include "base/base_plan.h"
#include "base/receiver_clock.h"
#include "base/survey_in.h"
#include "models/value_format.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QStackedWidget;

namespace gnss::config {
class SettingsEngine;
struct OperationReport;
} // namespace gnss::config
namespace gnss::sites {
class SiteStore;
}

namespace gnss::ui {

class ErrorSeriesPlot;
class ReceiverStateModel;

class BaseStationView : public QWidget {
    Q_OBJECT
public:
    BaseStationView(config::SettingsEngine *engine, ReceiverStateModel *state,
                    QWidget *parent = nullptr);

    void setSiteStore(sites::SiteStore *store);
    void setDisplayPrefs(const DisplayPrefs &prefs);

    // Where the base's position comes from (the source combo's order).
    enum class Source { Survey, ReceiverSurvey, Known };

    bool canBeBase() const { return roles_.has_value(); }
    bool surveying() const { return surveying_; }
    const base::SurveyIn &survey() const { return survey_; }
    // The position Set base would send (the survey's mean, or the typed one); nullopt with the
    // reason shown when there is none or it is malformed.
    std::optional<wgs84::Ecef> wantedPosition(QString *why = nullptr) const;

public slots:
    void readBase();
    void startSurvey();
    void stopSurvey();
    void setBase();

signals:
    void message(const QString &text); // for the status bar

private:
    void onDialect();
    void onEpoch();
    void onFinished(const config::OperationReport &r);
    void showStatus();
    void showSurvey();
    void fillChoices();
    // The receiver's values as the settings engine knows them.
    std::function<std::optional<std::string>(std::string_view)> known() const;
    // `q` with the form's station, interval and port, planned.
    base::BasePlan planWithForm(base::BaseRequest q) const;
    void pickSite(const QString &name);
    void saveSite();

    QPointer<config::SettingsEngine> engine_;
    ReceiverStateModel *state_;
    sites::SiteStore *sites_ = nullptr;
    DisplayPrefs prefs_;
    std::optional<base::BaseRoles> roles_;
    base::SurveyIn survey_;
    bool surveying_ = false;
    double receiverSurveyStart_ = -1; // the receiver's own averaging: its clock when it began
    std::optional<std::string> positionBefore_;
    base::ReceiverClock clock_;
    enum class Pending { None, Read, Apply, Save, ReadPosition } pending_ = Pending::None;
    bool saveAfterApply_ = false;
    // Asked for while the engine ran another operation (the Settings dock's read on connect, a
    // read-back): done when it ends, not refused.
    bool readWhenFree_ = false;
    bool setWhenFree_ = false;
    void runWhenFree();

    QLabel *unsupported_;
    QWidget *body_;
    QLabel *status_;
    QLabel *warning_;
    QComboBox *source_;
    QStackedWidget *sourcePages_;
    // Survey by the workbench.
    QComboBox *goal_;
    QDoubleSpinBox *goalValue_;
    QPushButton *surveyButton_;
    QProgressBar *progress_;
    QLabel *surveyText_;
    ErrorSeriesPlot *convergence_;
    // By the receiver.
    QSpinBox *receiverMinutes_;
    QPushButton *receiverButton_;
    QLabel *receiverText_;
    // Known.
    QComboBox *format_;
    QLineEdit *position_;
    QCheckBox *msl_;
    QPushButton *sitesButton_;
    // Common.
    QDoubleSpinBox *antenna_;
    QSpinBox *station_;
    QComboBox *interval_;
    QComboBox *port_;
    QCheckBox *saveFlash_;
    QPushButton *setButton_;
    QListWidget *verdicts_;
};

} // namespace gnss::ui
