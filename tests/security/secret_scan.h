#pragma once
// Test helper for the security suites: the forms a caster's credentials could leak in (the
// password, "user:password", their Base64 as in the Authorization header), and where in a text
// or a folder of files any of them is found.
#include "ntrip/base64.h"

#include <QByteArray>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QList>
#include <QString>
#include <QStringList>

namespace gnss::test {

// Distinctive: found nowhere by chance, so any hit is a leak.
inline const QByteArray kSecretUser = "rover7";
inline const QByteArray kSecretPassword = "Pw-7zXkq93-unseen";

struct SecretForms {
    QList<QByteArray> forms;
    explicit SecretForms(const QByteArray &user = kSecretUser,
                         const QByteArray &password = kSecretPassword) {
        const QByteArray pair = user + ':' + password;
        forms = {password, pair, QByteArray::fromStdString(ntrip::base64Encode(pair.toStdString())),
                 QByteArray::fromStdString(ntrip::base64Encode(password.toStdString()))};
    }
    // The first form found in `text` (empty when none is).
    QByteArray foundIn(const QByteArray &text) const {
        for (const QByteArray &f : forms)
            if (text.contains(f)) return f;
        return {};
    }
    // "FILE holds FORM" for every file under `dir` holding a form; empty when none does.
    QStringList filesHolding(const QString &dir) const {
        QStringList hits;
        QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            QFile f(path);
            if (!f.open(QIODevice::ReadOnly)) continue;
            if (const QByteArray hit = foundIn(f.readAll()); !hit.isEmpty())
                hits << QStringLiteral("%1 holds %2").arg(path, QString::fromLatin1(hit));
        }
        return hits;
    }
};

} // namespace gnss::test
