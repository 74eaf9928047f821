#include "gui/password_keychain.h"

#ifdef GNSS_HAVE_KEYCHAIN
#include <qt6keychain/keychain.h>
#endif

namespace gnss::app {

namespace {
#ifdef GNSS_HAVE_KEYCHAIN
const QString kService = QStringLiteral("gnss-workbench");
#endif
} // namespace

bool PasswordKeychain::available() {
#ifdef GNSS_HAVE_KEYCHAIN
    return true;
#else
    return false;
#endif
}

void PasswordKeychain::store(const QString &key, const QString &password) {
#ifdef GNSS_HAVE_KEYCHAIN
    auto *job = new QKeychain::WritePasswordJob(kService, this);
    job->setKey(key);
    job->setTextData(password);
    job->setInsecureFallback(false); // the keychain or nothing: never a plain file
    connect(job, &QKeychain::Job::finished, this, [this](QKeychain::Job *j) {
        emit stored(j->error() == QKeychain::NoError ? QString() : j->errorString());
    });
    job->start();
#else
    Q_UNUSED(key);
    Q_UNUSED(password);
    emit stored(tr("this build has no keychain support"));
#endif
}

void PasswordKeychain::recall(const QString &key) {
#ifdef GNSS_HAVE_KEYCHAIN
    auto *job = new QKeychain::ReadPasswordJob(kService, this);
    job->setKey(key);
    connect(job, &QKeychain::Job::finished, this, [this](QKeychain::Job *j) {
        auto *read = static_cast<QKeychain::ReadPasswordJob *>(j);
        emit recalled(read->error() == QKeychain::NoError ? read->textData() : QString(),
                      read->error() == QKeychain::NoError ? QString() : read->errorString());
    });
    job->start();
#else
    Q_UNUSED(key);
    emit recalled({}, tr("this build has no keychain support"));
#endif
}

void PasswordKeychain::forget(const QString &key) {
#ifdef GNSS_HAVE_KEYCHAIN
    auto *job = new QKeychain::DeletePasswordJob(kService, this);
    job->setKey(key);
    job->start(); // nothing to say when there was none
#else
    Q_UNUSED(key);
#endif
}

} // namespace gnss::app
