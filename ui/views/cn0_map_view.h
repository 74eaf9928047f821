#pragma once
// Cn0MapView: the polar C/N0 map of one receiver: the sky cut into cells of 10° of azimuth and
// 10° of elevation, each coloured by the mean C/N0 of every signal seen in it (or by how many
// were), north up, the zenith in the middle. Obstructions and multipath show as weak or empty
// cells. From the receiver's signal history (live since it connected; a whole log or a range).
#include <QWidget>

class QComboBox;

namespace gnss::ui {

class SignalHistoryModel;

class Cn0MapView : public QWidget {
    Q_OBJECT
public:
    enum class Show { MeanCn0, Count };
    explicit Cn0MapView(SignalHistoryModel *model, QWidget *parent = nullptr);
    void setShow(Show s);
    Show shown() const { return show_; }
    QSize minimumSizeHint() const override { return {120, 80}; }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    SignalHistoryModel *model_;
    QComboBox *mode_;
    Show show_ = Show::MeanCn0;
};

} // namespace gnss::ui
