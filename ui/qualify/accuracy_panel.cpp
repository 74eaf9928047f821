// The accuracy panel: a reference field, the statistics table and the error histogram.
#include "qualify/accuracy_panel.h"

#include "qualify/qualify_plots.h"
#include "sites/site_store.h"
#include "style/gnss_style.h"
#include "widgets/read_only_table.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

namespace gnss::ui {

AccuracyPanel::AccuracyPanel(QWidget *parent) : QWidget(parent) {
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *form = new QFormLayout;
    reference_ = new QLineEdit(this);
    reference_->setObjectName("accuracyReference");
    reference_->setPlaceholderText(tr("LAT,LON[,HEIGHT] — empty: the mean of the positions"));
    reference_->setToolTip(tr("A known point in degrees and, for the vertical error, its height "
                              "above the ellipsoid in metres: 55.7522,37.6156,180.2"));
    auto *row = new QHBoxLayout;
    row->addWidget(reference_, 1);
    // One button, short: the log statistics dock is narrow. Its menu: the sites to take as the
    // reference, and the mean of the positions shown kept as a new one.
    siteButton_ = new QToolButton(this);
    siteButton_->setObjectName("accuracySite");
    siteButton_->setText(tr("Sites"));
    siteButton_->setToolTip(tr("Use a site of your site list as the reference, or keep the mean "
                               "of these positions as a site (a survey-in by the workbench)"));
    siteButton_->setPopupMode(QToolButton::InstantPopup);
    siteButton_->setMenu(new QMenu(siteButton_));
    row->addWidget(siteButton_);
    siteButton_->hide();
    form->addRow(tr("Reference:"), row);
    layout->addLayout(form);
    // The list as it is now (gnss-cli may have changed it) each time the menu opens.
    connect(siteButton_->menu(), &QMenu::aboutToShow, this, [this] {
        QMenu *menu = siteButton_->menu();
        menu->clear();
        sites::SiteList list;
        QString error;
        if (!store_ || !store_->load(list, error)) {
            menu->addAction(error.isEmpty() ? tr("No site list") : error)->setEnabled(false);
            return;
        }
        if (list.sites().empty())
            menu->addAction(tr("No sites yet (gnss-cli sites add, or save the mean below)"))
                    ->setEnabled(false);
        for (const sites::Site &site : list.sites()) {
            const QString name = QString::fromStdString(site.name);
            menu->addAction(name, this, [this, name] { useSite(name); });
        }
        menu->addSeparator();
        QAction *save = menu->addAction(tr("Save the mean as a site…"), this, [this] {
            bool ok = false;
            const QString name = QInputDialog::getText(this, tr("Save as site"), tr("Site name:"),
                                                       QLineEdit::Normal, {}, &ok);
            if (!ok) return;
            QString why;
            if (!saveMeanAsSite(name, &why)) emit message(why);
        });
        save->setEnabled(lastMean_.has_value());
    });
    auto *split = split_ = new QSplitter(Qt::Horizontal, this);
    table_ = readOnlyTable(2, "accuracyTable", split);
    table_->setHorizontalHeaderLabels({tr("Statistic"), tr("Value")});
    // The plot: the histogram, or the errors over time (a choice, not tabs: the dock stays narrow).
    auto *plots = new QWidget(split);
    auto *plotsLayout = new QVBoxLayout(plots);
    plotsLayout->setContentsMargins(0, 0, 0, 0);
    auto *which = new QComboBox(plots);
    which->setObjectName("accuracyPlotChoice");
    which->addItem(tr("Histogram"));
    which->addItem(tr("Over time"));
    which->setToolTip(tr("The horizontal error's histogram, or the horizontal and vertical "
                         "errors epoch by epoch"));
    which->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    which->setMinimumContentsLength(8);
    auto *stack = new QStackedWidget(plots);
    histogram_ = new ErrorHistogram(stack);
    histogram_->setObjectName("accuracyHistogram");
    overTime_ = new ErrorSeriesPlot(stack);
    overTime_->setObjectName("accuracyOverTime");
    stack->addWidget(histogram_);
    stack->addWidget(overTime_);
    plotsLayout->addWidget(which);
    plotsLayout->addWidget(stack, 1);
    connect(which, &QComboBox::currentIndexChanged, stack, &QStackedWidget::setCurrentIndex);
    split->addWidget(table_);
    split->addWidget(plots);
    layout->addWidget(split, 1);
    connect(reference_, &QLineEdit::editingFinished, this, &AccuracyPanel::referenceChanged);
}

void AccuracyPanel::setSiteStore(const sites::SiteStore *store) {
    store_ = store;
    siteButton_->setVisible(store != nullptr);
}

bool AccuracyPanel::useSite(const QString &name, QString *why) {
    sites::SiteList list;
    QString error;
    if (!store_ || !store_->load(list, error)) {
        if (why) *why = error;
        return false;
    }
    const sites::Site *site = list.find(name.toStdString());
    if (!site) {
        if (why) *why = tr("No site named %1").arg(name);
        return false;
    }
    // The receiver reports its antenna's position: the mark plus the antenna height.
    const wgs84::Geodetic arp = site->antennaReferencePoint();
    QString text = QStringLiteral("%1,%2").arg(arp.latDeg, 0, 'f', 9).arg(arp.lonDeg, 0, 'f', 9);
    if (site->height) text += QStringLiteral(",%1").arg(arp.height, 0, 'f', 4);
    setReferenceText(text);
    emit message(tr("Reference: the site %1").arg(name));
    return true;
}

bool AccuracyPanel::saveMeanAsSite(const QString &name, QString *why) {
    auto fail = [why](const QString &text) {
        if (why) *why = text;
        return false;
    };
    if (!store_) return fail(tr("No site list"));
    if (!lastMean_) return fail(tr("No positions to average yet."));
    if (const std::string no = sites::nameProblem(name.toStdString()); !no.empty())
        return fail(QString::fromStdString(no));
    sites::SiteList list;
    QString error;
    if (!store_->load(list, error)) return fail(error);
    wgs84::Geodetic g;
    g.latDeg = lastMean_->latDeg;
    g.lonDeg = lastMean_->lonDeg;
    g.height = lastMean_->height.value_or(0);
    sites::Site site = sites::surveyInSite(name.toStdString(), g, lastCep95_, sites::todayUtc());
    if (!lastMean_->height) site.height.reset();
    if (list.add(site, false) != sites::SiteList::AddResult::Added)
        return fail(tr("A site named %1 is already in the list").arg(name));
    if (!store_->save(list, error)) return fail(error);
    emit message(
            tr("Saved the mean of %1 positions as the site %2").arg(positionsShown_).arg(name));
    return true;
}

void AccuracyPanel::setOrientation(Qt::Orientation o) {
    split_->setOrientation(o);
}

void AccuracyPanel::setUnits(UnitSystem u) {
    units_ = u;
}

std::optional<compare::ReferencePoint> AccuracyPanel::reference() const {
    const QString t = reference_->text().trimmed();
    if (t.isEmpty()) return std::nullopt;
    std::string why;
    return compare::ReferencePoint::parse(t.toStdString(), why);
}

bool AccuracyPanel::referenceValid() const {
    return reference_->text().trimmed().isEmpty() || reference().has_value();
}

void AccuracyPanel::setReferenceText(const QString &text) {
    reference_->setText(text);
    emit referenceChanged();
}

QString AccuracyPanel::referenceText() const {
    return reference_->text().trimmed();
}

QString AccuracyPanel::len(double metres, int decimals) const {
    return fmt::length(metres, decimals, units_);
}

void AccuracyPanel::addRow(const QString &name, const QString &value) {
    const int r = table_->rowCount();
    table_->insertRow(r);
    table_->setItem(r, 0, new QTableWidgetItem(name));
    table_->setItem(r, 1, new QTableWidgetItem(value));
}

QString AccuracyPanel::valueOf(const QString &name) const {
    for (int r = 0; r < table_->rowCount(); ++r)
        if (table_->item(r, 0)->text() == name) return table_->item(r, 1)->text();
    return {};
}

void AccuracyPanel::say(const QString &text) {
    // The first row: what the numbers are of (or why there are none); the dock stays short.
    addRow(tr("Positions"), text);
}

void AccuracyPanel::clearPlots() {
    histogram_->setValues({}, fmt::lengthUnit(units_), fmt::lengthFactor(units_), 0, 0);
    overTime_->setValues({}, {}, fmt::lengthUnit(units_), fmt::lengthFactor(units_));
}

void AccuracyPanel::show(const compare::PositionSet &positions) {
    table_->setRowCount(0);
    std::optional<compare::ReferencePoint> point = reference();
    const bool typed = point.has_value();
    if (!referenceValid()) {
        std::string why;
        compare::ReferencePoint::parse(reference_->text().trimmed().toStdString(), why);
        say(tr("The reference is not a point: %1").arg(QString::fromStdString(why)));
        clearPlots();
        return;
    }
    lastMean_ = positions.mean();
    positionsShown_ = qsizetype(positions.size());
    if (!point) point = lastMean_;
    if (!point || positions.size() == 0) {
        say(tr("No positions yet."));
        clearPlots();
        return;
    }
    const compare::Accuracy acc = positions.against(*point);
    const compare::AccuracyReport r = acc.report();
    lastCep95_ = r.cep95;
    say((typed ? tr("%n position(s) against the reference %1, %2", nullptr, int(r.positions))
               : tr("%n position(s) against their mean %1, %2 (no reference typed)", nullptr,
                    int(r.positions)))
                .arg(fmt::angle(point->latDeg, 7), fmt::angle(point->lonDeg, 7)));
    if (typed) {
        addRow(tr("Bias east"), len(r.biasEast));
        addRow(tr("Bias north"), len(r.biasNorth));
        addRow(tr("Bias up"), r.biasUp ? len(*r.biasUp) : fmt::dash());
    }
    addRow(tr("Horizontal mean"), len(r.horizontal.mean));
    addRow(tr("Horizontal median"), len(r.horizontal.median));
    addRow(tr("CEP50"), len(r.cep50));
    addRow(tr("CEP95"), len(r.cep95));
    addRow(tr("2DRMS"), len(r.drms2));
    addRow(tr("R95"), len(r.horizontal.p95));
    addRow(tr("Horizontal max"), len(r.horizontal.max));
    if (r.heights) {
        addRow(tr("Vertical mean"), len(r.vertical.mean));
        addRow(tr("Vertical median"), len(r.vertical.median));
        addRow(tr("Vertical 95%"), len(r.vertical.p95));
    }
    auto shares = [&](const compare::WithinShares &w) {
        QStringList parts;
        for (std::size_t i = 0; i < compare::kWithinMetres.size(); ++i)
            parts << tr("%1: %2%").arg(len(compare::kWithinMetres[i], 2),
                                       QString::number(w.percent[i], 'f', 1));
        return parts.join(QStringLiteral(", "));
    };
    addRow(tr("Within (all)"), shares(r.within));
    for (const auto &[fix, w] : r.withinByFix)
        addRow(tr("Within (%1, %n epoch(s))", nullptr, int(w.epochs)).arg(style::fixTypeLabel(fix)),
               shares(w));
    table_->resizeColumnToContents(0);
    histogram_->setValues(acc.horizontalErrors(), fmt::lengthUnit(units_),
                          fmt::lengthFactor(units_), r.cep50, r.cep95);
    overTime_->setValues(acc.horizontalErrors(), acc.verticalErrors(), fmt::lengthUnit(units_),
                         fmt::lengthFactor(units_));
}

} // namespace gnss::ui
