#pragma once
// The sources on sockets and ports (link transports, correction sources) keep a `closing_` flag
// that their signal handlers check, so that a connection closed on purpose reports nothing.

namespace gnss::link {

// Runs `close` with `closing` set.
template <class Close> void whileClosing(bool &closing, Close close) {
    closing = true;
    close();
    closing = false;
}

} // namespace gnss::link
