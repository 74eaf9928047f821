#pragma once
// MainWindow: menus, docks and the status bar. It wires; it does not decode or draw.
#include <QMainWindow>

namespace gnss::app {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);

signals:
    void openLogRequested(const QString &path);

private:
    void createMenus();
    void openLog();
    void about();

    QMenu *viewMenu_ = nullptr;
};

} // namespace gnss::app
