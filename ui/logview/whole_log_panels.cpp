#include "logview/whole_log_panels.h"
#include "logview/panel_layout.h"

#include "style/gnss_style.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace gnss::ui {

LogChartsPanel::LogChartsPanel(LogCursor *cursor, QWidget *parent) : QWidget(parent) {
    const auto [layout, row] = panelLayout(this, "logChartsPanel");
    quantity_ = new QComboBox(this);
    quantity_->setObjectName("logQuantity");
    using Q = LogPlot::Quantity;
    for (Q q : {Q::Altitude, Q::Speed, Q::Satellites, Q::Hdop, Q::Snr})
        quantity_->addItem(LogPlot::quantityName(q), int(q));
    row->addWidget(quantity_);
    auto *hint = new QLabel(tr("wheel: zoom · drag: pan · click: go there"), this);
    hint->setEnabled(false);
    row->addWidget(hint, 1);
    auto *all = new QPushButton(tr("Whole log"), this);
    all->setObjectName("logPlotAll");
    row->addWidget(all);
    plot_ = new LogPlot(cursor, this);
    layout->addWidget(plot_, 1);
    connect(quantity_, &QComboBox::currentIndexChanged, this,
            [this] { plot_->setQuantity(static_cast<Q>(quantity_->currentData().toInt())); });
    connect(all, &QPushButton::clicked, plot_, &LogPlot::showAll);
}

LogTrackPanel::LogTrackPanel(LogCursor *cursor, QWidget *parent) : QWidget(parent) {
    const auto [layout, row] = panelLayout(this, "logTrackPanel");
    row->addWidget(new QLabel(tr("Reference:"), this));
    reference_ = new QLineEdit(this);
    reference_->setObjectName("trackReference");
    reference_->setPlaceholderText(tr("the mean position"));
    reference_->setToolTip(tr("Latitude, longitude in degrees (55.75, 37.62); empty for the "
                              "mean of the log's positions"));
    reference_->setClearButtonEnabled(true);
    row->addWidget(reference_, 1);
    auto *fit = new QPushButton(tr("Fit"), this);
    fit->setObjectName("trackFit");
    row->addWidget(fit);
    message_ = new QLabel(this);
    message_->setStyleSheet(style::textColorCss(style::errorColor()));
    message_->hide();
    layout->addWidget(message_);
    track_ = new LogTrack(cursor, this);
    layout->addWidget(track_, 1);
    connect(reference_, &QLineEdit::editingFinished, this,
            [this] { setReferenceText(reference_->text()); });
    connect(fit, &QPushButton::clicked, track_, &LogTrack::fit);
}

bool LogTrackPanel::setReferenceText(const QString &text) {
    reference_->setText(text);
    const QString t = text.trimmed();
    if (t.isEmpty()) {
        message_->hide();
        track_->setReference(std::nullopt);
        return true;
    }
    const QStringList parts =
            t.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
    bool okLat = false, okLon = false;
    const double lat = parts.size() == 2 ? parts[0].toDouble(&okLat) : 0;
    const double lon = parts.size() == 2 ? parts[1].toDouble(&okLon) : 0;
    if (!okLat || !okLon || std::abs(lat) > 90 || std::abs(lon) > 180) {
        message_->setText(tr("Write the reference as latitude, longitude in degrees: 55.75, "
                             "37.62"));
        message_->show();
        return false;
    }
    message_->hide();
    track_->setReference(std::pair{lat, lon});
    return true;
}

} // namespace gnss::ui
