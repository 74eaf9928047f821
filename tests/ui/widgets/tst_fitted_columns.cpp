// FittedColumns: a table's columns fit their contents, measured when rows come or go and at
// most once an interval when values change (not at every change, as ResizeToContents does); a
// column the user sized keeps its width. Counted, not timed.
#include "widgets/fitted_columns.h"

#include <QHeaderView>
#include <QStandardItemModel>
#include <QTableView>
#include <QTest>

using gnss::ui::FittedColumns;

namespace {

// Counts how often the view is asked to measure a column.
class CountingTable : public QTableView {
public:
    int sizeHintForColumn(int column) const override {
        ++measured;
        return QTableView::sizeHintForColumn(column);
    }
    mutable int measured = 0;
};

} // namespace

class TstFittedColumns : public QObject {
    Q_OBJECT
private slots:
    void columnsFitWhatRowsBring();
    void manyValueChangesAreMeasuredOncePerInterval();
    void aColumnTheUserSizedKeepsItsWidth();
    void theStretchedLastColumnIsLeftToStretch();
};

void TstFittedColumns::columnsFitWhatRowsBring() {
    QStandardItemModel model(0, 2);
    CountingTable view;
    view.setModel(&model);
    view.resize(600, 300);
    view.show();
    auto *fitter = new FittedColumns(&view, view.horizontalHeader(), 60000);
    QCOMPARE(view.horizontalHeader()->sectionResizeMode(0), QHeaderView::Interactive);
    const QString wide = QString(40, QLatin1Char('W'));
    model.appendRow({new QStandardItem(wide), new QStandardItem("1")});
    QCOMPARE(fitter->fits(), 0); // on the next turn of the event loop, not inside the insert
    QTRY_COMPARE(fitter->fits(), 1);
    const int textWidth = view.fontMetrics().horizontalAdvance(wide);
    QVERIFY2(view.columnWidth(0) >= textWidth,
             qPrintable(QString("%1 < %2").arg(view.columnWidth(0)).arg(textWidth)));
    // Rows going away narrow it again.
    model.removeRow(0);
    model.appendRow({new QStandardItem("x"), new QStandardItem("1")});
    QTRY_COMPARE(fitter->fits(), 2);
    QVERIFY(view.columnWidth(0) < textWidth);
}

void TstFittedColumns::manyValueChangesAreMeasuredOncePerInterval() {
    QStandardItemModel model(0, 3);
    for (int r = 0; r < 60; ++r)
        model.appendRow(
                {new QStandardItem("G12"), new QStandardItem("45"), new QStandardItem("1")});
    CountingTable view;
    view.setModel(&model);
    view.resize(600, 400);
    view.show();
    // An interval no machine runs the loop below in, however slow or loaded (a sanitizer build
    // on a busy CI runner took longer than 200 ms): the count cannot depend on the clock.
    auto *fitter = new FittedColumns(&view, view.horizontalHeader(), 600000);
    QTRY_COMPARE(fitter->fits(), 1);
    const int before = view.measured;
    // A whole table rewritten 100 times, the event loop turning between (as at 20 Hz).
    for (int k = 0; k < 100; ++k) {
        emit model.dataChanged(model.index(0, 0), model.index(59, 2));
        QCoreApplication::processEvents();
    }
    // No measuring while the interval runs; ResizeToContents measured at each change.
    QCOMPARE(fitter->fits(), 1);
    QCOMPARE(view.measured, before);
    delete fitter;

    // A longer value is fitted once the interval is over: not at the change, at the timer.
    auto *quick = new FittedColumns(&view, view.horizontalHeader(), 50);
    QTRY_COMPARE(quick->fits(), 1);
    model.setItem(7, 1, new QStandardItem(QString(30, QLatin1Char('8'))));
    QCOMPARE(quick->fits(), 1);
    QTRY_COMPARE(quick->fits(), 2);
    QVERIFY(view.columnWidth(1) >= view.fontMetrics().horizontalAdvance(QString(30, '8')));
    QVERIFY(view.measured > before);
}

void TstFittedColumns::aColumnTheUserSizedKeepsItsWidth() {
    QStandardItemModel model(0, 2);
    model.appendRow({new QStandardItem("a"), new QStandardItem("b")});
    QTableView view;
    view.setModel(&model);
    view.show();
    auto *fitter = new FittedColumns(&view, view.horizontalHeader(), 60000);
    QTRY_COMPARE(fitter->fits(), 1);
    view.horizontalHeader()->resizeSection(0, 333); // what a drag of the section's edge does
    model.appendRow({new QStandardItem(QString(80, 'W')), new QStandardItem(QString(20, 'W'))});
    QTRY_COMPARE(fitter->fits(), 2);
    QCOMPARE(view.columnWidth(0), 333);
    QVERIFY(view.columnWidth(1) >= view.fontMetrics().horizontalAdvance(QString(20, 'W')));
}

void TstFittedColumns::theStretchedLastColumnIsLeftToStretch() {
    QStandardItemModel model(0, 2);
    model.appendRow({new QStandardItem("a"), new QStandardItem("b")});
    QTableView view;
    view.setModel(&model);
    view.horizontalHeader()->setStretchLastSection(true);
    view.resize(700, 200);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    auto *fitter = new FittedColumns(&view, view.horizontalHeader(), 60000);
    QTRY_COMPARE(fitter->fits(), 1);
    const int stretched = view.columnWidth(1);
    QVERIFY2(stretched > 300, qPrintable(QString::number(stretched)));
    model.appendRow({new QStandardItem("c"), new QStandardItem("d")});
    QTRY_COMPARE(fitter->fits(), 2);
    QCOMPARE(view.columnWidth(1), stretched);
}

QTEST_MAIN(TstFittedColumns)
#include "tst_fitted_columns.moc"
