#pragma once
// Test helpers for the real window: a receiver connected with an epoch in, and a named child
// widget (a warning names the one that is missing, so a renamed widget fails clearly).
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "session/receiver_link.h"

#include <QWidget>

namespace gnss::test {

inline bool connectedWithEpochs(ui::ReceiverSession *s) {
    return s->link()->state() == session::ReceiverLink::State::Connected &&
           s->state()->epochCount() > 0;
}

template <class W> W *child(QWidget *root, const char *name) {
    auto *w = root->findChild<W *>(QLatin1String(name));
    if (!w) qWarning("no %s", name);
    return w;
}

} // namespace gnss::test
