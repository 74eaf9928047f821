#pragma once
// Test helper: models + session, fed with sentences (checksums added) through a decoder of
// its own, as the link's decoder feeds the session in the application.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/model_feed.h"
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
    ui::ModelFeed session{registry, {&state, &satellites, &messages, &console}};
    StreamDecoder decoder{registry};

    SessionFixture() { session.setCounterSource(&decoder); }

    void feedBytes(const QByteArray &bytes) {
        session.noteBytes(bytes);
        decoder.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())),
                     [this](const SentenceEvent &ev) { session.consume(ev, decoder.dialect()); });
    }

    // Each body gets "$" and its checksum unless it already starts with '$'.
    void feed(std::initializer_list<std::string> lines) {
        QByteArray bytes;
        for (const auto &l : lines) {
            bytes += QByteArray::fromStdString(l.rfind('$', 0) == 0 ? l : buildSentence(l));
            bytes += "\r\n";
        }
        feedBytes(bytes);
        session.refresh();
    }
};

} // namespace gnss::test
