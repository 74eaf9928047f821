#include "soak_transport.h"

#include "builtin/simulators.h"
#include "core/sentence_builder.h"

#include <QElapsedTimer>

namespace gnss::soak {
namespace {

// The NV08C-RTK's output list on the soak's port: its proprietary sentences only (the standard
// ones come from SoakSky), at its 5 Hz PVT rate.
constexpr const char *kNvsOutput[] = {
        "PNVGRZB,PORT,1", // clear
        "PNVGRZB,PORT,1,PNVGBSS,5,PNVGBLS,1,PNVGSDP,1,PNVGIMU,1,PNVGTME,1,PNVGTMU,1,PNVGTMC,1,"
        "PNVGVOG,1,PNVGSDH,1",
};

} // namespace

SoakTransport::SoakTransport(const DialectRegistry &registry, QObject *parent)
    : Transport(parent), registry_(registry) {
    timer_.setInterval(0);
    connect(&timer_, &QTimer::timeout, this, &SoakTransport::tick);
}

SoakTransport::~SoakTransport() = default;

bool SoakTransport::open() {
    sim::SimOptions options;
    options.internalBase = true;
    nvs_ = sim::makeReceiver("nvs", options);
    if (!nvs_) {
        fail(tr("The simulator has no NVS receiver"), false);
        return false;
    }
    nvs_->setLineBaud(nvs_->baud());
    for (const char *body : kNvsOutput) nvs_->receive(gnss::buildSentence(body) + "\r\n");
    timer_.start();
    setState(State::Open);
    return true;
}

void SoakTransport::close() {
    timer_.stop();
    setState(State::Closed);
}

QString SoakTransport::description() const {
    return tr("soak receiver (20 Hz, %1 satellites)").arg(sky_.inView());
}

int SoakTransport::baud() const {
    return nvs_ ? nvs_->lineBaud() : 0;
}

bool SoakTransport::setBaud(int baud) {
    if (nvs_) nvs_->setLineBaud(baud);
    return true;
}

bool SoakTransport::writeBytes(const QByteArray &bytes) {
    if (!nvs_) return false;
    nvs_->receive(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    return true;
}

void SoakTransport::tick() {
    // Slices until the budget is spent, then the event loop runs (timers, repaints) before the
    // next pass: the views repaint at most 1000 / kPassBudgetMs times a real second.
    QElapsedTimer pass;
    pass.start();
    while (nvs_ && simulatedSeconds() < endSeconds_ && pass.elapsed() < kPassBudgetMs &&
           state() == State::Open)
        slice();
}

void SoakTransport::slice() {
    QByteArray out;
    const int epochs = int(kSliceSeconds * SoakSky::kRateHz);
    for (int i = 0; i < epochs; ++i) {
        out += sky_.epoch(epoch_++);
        nvs_->advance(1.0 / SoakSky::kRateHz);
        // Whole lines only; the proprietary ones (and replies) pass, the receiver's standard
        // ones would duplicate SoakSky's.
        partial_ += QByteArray::fromStdString(nvs_->takeOutput());
        qsizetype start = 0;
        for (qsizetype end; (end = partial_.indexOf('\n', start)) >= 0; start = end + 1)
            if (partial_.at(start) == '$' && start + 1 < partial_.size() &&
                partial_.at(start + 1) == 'P')
                out += partial_.mid(start, end + 1 - start);
        partial_.remove(0, start);
    }
    emit bytesReceived(out);
}

} // namespace gnss::soak
