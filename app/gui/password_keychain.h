#pragma once
// PasswordKeychain: a caster's password kept in the desktop's keychain (Secret Service, KWallet:
// Debian's qtkeychain-qt6), only when the user asks, never in the settings file. Asynchronous:
// the answers come as signals. Without qtkeychain at build time, available() is false and every
// request answers with an error at once.
#include <QObject>
#include <QString>

namespace gnss::app {

class PasswordKeychain : public QObject {
    Q_OBJECT
public:
    explicit PasswordKeychain(QObject *parent = nullptr) : QObject(parent) {}

    static bool available();
    // Stores, fetches or removes the password kept under `key` ("ntrip:user@host:port").
    void store(const QString &key, const QString &password);
    void recall(const QString &key);
    void forget(const QString &key);

signals:
    // `error` empty when it worked.
    void stored(const QString &error);
    void recalled(const QString &password, const QString &error);
};

} // namespace gnss::app
