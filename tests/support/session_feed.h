#pragma once
// Test helper: models + session, fed with sentences (checksums added).
#include "core/sentence_builder.h"
#include "dialects.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"

#include <QByteArray>
#include <initializer_list>
#include <string>

namespace gnss::test {

struct SessionFixture {
    DialectRegistry registry = makeBuiltinRegistry();
    ui::ReceiverStateModel state;
    ui::SatelliteModel satellites;
    ui::MessageStatsModel messages;
    ui::ConsoleModel console;
    ui::ReceiverSession session{registry, {&state, &satellites, &messages, &console}};

    // Each body gets "$" and its checksum unless it already starts with '$'.
    void feed(std::initializer_list<std::string> lines) {
        QByteArray bytes;
        for (const auto &l : lines) {
            bytes += QByteArray::fromStdString(l.rfind('$', 0) == 0 ? l : buildSentence(l));
            bytes += "\r\n";
        }
        session.feed(bytes);
        session.refresh();
    }
};

} // namespace gnss::test
