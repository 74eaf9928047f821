#include "main_window.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

namespace gnss::app {

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent) {
    setWindowTitle(tr("GNSS Workbench"));
    setObjectName("MainWindow");
    setDockNestingEnabled(true);
    createMenus();
    auto *state = new QLabel(tr("Not connected"), this);
    state->setObjectName("connectionState");
    statusBar()->addWidget(state);
    resize(1280, 800);
}

void MainWindow::createMenus() {
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *open = file->addAction(tr("&Open Log..."), this, &MainWindow::openLog);
    open->setShortcut(QKeySequence::Open);
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), qApp, &QApplication::closeAllWindows);
    quit->setShortcut(QKeySequence::Quit);

    QMenu *receiver = menuBar()->addMenu(tr("&Receiver"));
    receiver->setObjectName("receiverMenu");
    receiver->addAction(tr("&Connect"))->setShortcut(QKeySequence(tr("Ctrl+K")));
    receiver->addAction(tr("&Disconnect"))->setShortcut(QKeySequence(tr("Ctrl+Shift+K")));

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->setObjectName("viewMenu");

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About GNSS Workbench"), this, &MainWindow::about);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::openLog() {
    const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Log"), QString(),
            tr("NMEA logs (*.nmea *.log *.txt);;All files (*)"));
    if (!path.isEmpty()) emit openLogRequested(path);
}

void MainWindow::about() {
    QMessageBox::about(this, tr("About GNSS Workbench"),
                       tr("<b>GNSS Workbench</b> %1<br>Configure and monitor NVS NV08C-RTK, "
                          "GeoStar GeoS-5, Nemerix and NMEA-0183 receivers.")
                               .arg(QApplication::applicationVersion()));
}

} // namespace gnss::app
