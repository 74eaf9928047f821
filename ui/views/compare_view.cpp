#include "views/compare_view.h"

#include "models/compare_model.h"
#include "views/compare_plot.h"
#include "widgets/read_only_table.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QMenu>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

namespace gnss::ui {

namespace {

QString label(SatelliteRef s) {
    return QString::fromStdString(satelliteLabel(s));
}

QString systemName(Constellation c) {
    const std::string_view n = toString(c);
    return QString::fromLatin1(n.data(), qsizetype(n.size()));
}

QTableWidgetItem *cell(const QString &text,
                       Qt::Alignment align = Qt::AlignRight | Qt::AlignVCenter) {
    auto *item = new QTableWidgetItem(text);
    item->setTextAlignment(align);
    return item;
}

QString metres(double v) {
    return QString::number(v, 'f', 3);
}

} // namespace

CompareView::CompareView(CompareModel *model, QWidget *parent) : QWidget(parent), model_(model) {
    setObjectName("compareView");
    // Low on a laptop: the choices sit beside the tabs, the note above the summary.
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto *corner = new QWidget(this);
    auto *bar = new QHBoxLayout(corner);
    bar->setContentsMargins(0, 0, 0, 0);
    window_ = new QComboBox(corner);
    window_->setObjectName("compareWindow");
    window_->setToolTip(tr("The numbers, the plots and the export are over this window"));
    for (int minutes : {1, 5, 15, 60})
        window_->addItem(tr("last %n minute(s)", nullptr, minutes), minutes * 60);
    window_->setCurrentIndex(window_->findData(model_->windowSeconds()));
    bar->addWidget(window_);
    receiver_ = new QComboBox(corner);
    receiver_->setObjectName("compareReceiver");
    receiver_->setToolTip(tr("The receiver the plots draw against the reference"));
    receiver_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    bar->addWidget(receiver_);
    auto *exportButton = new QToolButton(corner);
    exportButton->setObjectName("compareExport");
    exportButton->setText(tr("Export"));
    exportButton->setPopupMode(QToolButton::InstantPopup);
    auto *menu = new QMenu(exportButton);
    menu->addAction(tr("CSV, one row per matched epoch..."), this,
                    [this] { emit exportRequested(false); });
    menu->addAction(tr("JSON, the numbers over the window..."), this,
                    [this] { emit exportRequested(true); });
    exportButton->setMenu(menu);
    bar->addWidget(exportButton);
    tabs_ = new QTabWidget(this);
    tabs_->setCornerWidget(corner, Qt::TopRightCorner);
    summary_ = readOnlyTable(1, "compareSummary", this);
    signals_ = readOnlyTable(3, "compareSignals", this);
    // As low as the other docks of the bottom row: the window fits a laptop.
    for (QTableWidget *t : {summary_, signals_}) t->setMinimumSize(160, 60);
    plot_ = new ComparePlot(model_, this);
    tabs_->addTab(summary_, tr("Summary"));
    tabs_->addTab(signals_, tr("Signals"));
    tabs_->addTab(plot_, tr("Plots"));
    layout->addWidget(tabs_, 1);
    connect(window_, &QComboBox::activated, this, [this] {
        model_->setWindowSeconds(window_->currentData().toInt());
        refresh();
    });
    connect(receiver_, &QComboBox::activated, this,
            [this] { plot_->setReceiver(receiver_->currentData().toInt()); });
    connect(model_, &CompareModel::changed, this, &CompareView::refresh);
    refresh();
}

void CompareView::refresh() {
    const auto &receivers = model_->receivers();
    // The receivers the plots can show (each against the first).
    QStringList names;
    for (int i = 1; i < receivers.size(); ++i) names << receivers[i].name;
    QStringList shown;
    for (int i = 0; i < receiver_->count(); ++i) shown << receiver_->itemText(i);
    if (names != shown) { // rebuilt only when the receivers change (an open list stays open)
        const int chosen = receiver_->currentData().toInt();
        receiver_->clear();
        for (int i = 1; i < receivers.size(); ++i) receiver_->addItem(receivers[i].name, i);
        const int at = receiver_->findData(chosen);
        receiver_->setCurrentIndex(at >= 0 ? at : 0);
    }
    plot_->setReceiver(receiver_->currentData().toInt());
    // What the numbers are over, in the summary's corner.
    if (receivers.size() < 2) {
        note_ = tr("Connect two or more receivers to compare them (Add receiver)");
    } else {
        note_ = tr("%1 matched epochs (%2 since the start)")
                        .arg(model_->matches().size())
                        .arg(model_->matchedEpochs());
    }
    summary_->setToolTip(tr("Receivers are matched epoch by epoch on UTC time; each difference is "
                            "a receiver minus the first, %1.")
                                 .arg(receivers.isEmpty() ? QString() : receivers[0].name));
    fillSummary();
    fillSignals();
}

void CompareView::fillSummary() {
    const auto &receivers = model_->receivers();
    const compare::Report &r = model_->report();
    struct Row {
        QString name;
        std::vector<QString> values; // per receiver
    };
    std::vector<Row> rows;
    auto row = [&](const QString &name) -> Row & {
        for (Row &x : rows)
            if (x.name == name) return x;
        rows.push_back({name, std::vector<QString>(std::size_t(receivers.size()))});
        return rows.back();
    };
    for (int i = 0; i < receivers.size() && std::size_t(i) < r.receivers.size(); ++i) {
        const auto &rr = r.receivers[std::size_t(i)];
        for (const auto &f : rr.fixes)
            row(tr("Fix %1 (share of epochs)")
                        .arg(QString::fromLatin1(toString(f.fix).data(),
                                                 qsizetype(toString(f.fix).size()))))
                    .values[std::size_t(i)] = QStringLiteral("%1 %").arg(
                    100.0 * double(f.epochs) / double(rr.epochs), 0, 'f', 1);
    }
    for (std::size_t k = 0; k < r.pairs.size(); ++k) {
        const compare::PairReport &p = r.pairs[k];
        const std::size_t i = k + 1;
        auto spread = [&](const QString &what, const compare::Spread &s) {
            if (s.count == 0) return;
            row(tr("%1 mean (m)").arg(what)).values[i] = metres(s.mean);
            row(tr("%1 median (m)").arg(what)).values[i] = metres(s.median);
            row(tr("%1 p95 (m)").arg(what)).values[i] = metres(s.p95);
        };
        spread(tr("East"), p.east);
        spread(tr("North"), p.north);
        spread(tr("Up"), p.up);
        spread(tr("Horizontal"), p.horizontal);
        if (p.horizontal.count) {
            row(tr("CEP50 (m)")).values[i] = metres(p.cep50);
            row(tr("CEP95 (m)")).values[i] = metres(p.cep95);
        }
        if (p.cn0.count) {
            row(tr("C/N0 difference, mean (dB)")).values[i] = QString::number(p.cn0.mean, 'f', 2);
            row(tr("C/N0 difference, p95 (dB)")).values[i] = QString::number(p.cn0.p95, 'f', 2);
        }
        for (const auto &c : p.perConstellation)
            row(tr("C/N0 %1: mean, p95 (dB), satellites").arg(systemName(c.system))).values[i] =
                    tr("%1, %2 (%3)")
                            .arg(c.difference.mean, 0, 'f', 2)
                            .arg(c.difference.p95, 0, 'f', 2)
                            .arg(c.satellites);
        auto sats = [](const std::vector<compare::SatelliteCount> &v) {
            QStringList out;
            for (const auto &s : v) out << label(s.sat);
            return out.isEmpty() ? QStringLiteral("—") : out.join(' ');
        };
        row(tr("Only in the reference")).values[i] = sats(p.onlyInReference);
        row(tr("Only in this one")).values[i] = sats(p.onlyInThis);
    }
    summary_->setUpdatesEnabled(false);
    summary_->setColumnCount(int(receivers.size()) + 1);
    QStringList headers{note_};
    for (const auto &x : receivers) headers << x.name;
    summary_->setHorizontalHeaderLabels(headers);
    summary_->setRowCount(int(rows.size()));
    for (int k = 0; k < int(rows.size()); ++k) {
        summary_->setItem(k, 0, cell(rows[std::size_t(k)].name, Qt::AlignLeft | Qt::AlignVCenter));
        for (int i = 0; i < receivers.size(); ++i)
            summary_->setItem(k, i + 1, cell(rows[std::size_t(k)].values[std::size_t(i)]));
    }
    summary_->resizeColumnsToContents();
    summary_->setUpdatesEnabled(true);
}

void CompareView::fillSignals() {
    const auto &receivers = model_->receivers();
    const int n = int(receivers.size());
    // Satellite and signal → each receiver's latest C/N0.
    std::map<std::tuple<int, int, int>, std::vector<int>> levels;
    for (int i = 0; i < n; ++i) {
        const compare::Observation *o = model_->latest(i);
        if (!o) continue;
        for (const compare::SignalLevel &l : o->levels) {
            if (l.sat.system == Constellation::Unknown) continue;
            auto &v = levels[{int(l.sat.system), l.sat.prn, l.signalId}];
            v.resize(std::size_t(n), -1);
            v[std::size_t(i)] = l.cn0;
        }
    }
    signals_->setUpdatesEnabled(false);
    signals_->setColumnCount(2 + n + std::max(0, n - 1));
    QStringList headers{tr("Satellite"), tr("Signal")};
    for (const auto &x : receivers) headers << tr("%1 (dB-Hz)").arg(x.name);
    for (int i = 1; i < n; ++i) headers << tr("%1 − %2").arg(receivers[i].name, receivers[0].name);
    signals_->setHorizontalHeaderLabels(headers);
    signals_->setRowCount(int(levels.size()));
    int rowIndex = 0;
    const QString none = QStringLiteral("—");
    for (const auto &[key, v] : levels) {
        const SatelliteRef sat{Constellation(std::get<0>(key)), std::get<1>(key)};
        signals_->setItem(rowIndex, 0, cell(label(sat), Qt::AlignLeft | Qt::AlignVCenter));
        signals_->setItem(rowIndex, 1, cell(QString::number(std::get<2>(key))));
        for (int i = 0; i < n; ++i)
            signals_->setItem(
                    rowIndex, 2 + i,
                    cell(v[std::size_t(i)] >= 0 ? QString::number(v[std::size_t(i)]) : none));
        for (int i = 1; i < n; ++i) {
            const bool both = v[0] >= 0 && v[std::size_t(i)] >= 0;
            signals_->setItem(
                    rowIndex, 1 + n + i,
                    cell(both ? QString::asprintf("%+d", v[std::size_t(i)] - v[0]) : none));
        }
        ++rowIndex;
    }
    signals_->setUpdatesEnabled(true);
}

} // namespace gnss::ui
