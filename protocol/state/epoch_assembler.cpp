#include "state/epoch_assembler.h"

#include "nmea/nmea_messages.h"

#include <algorithm>

namespace gnss {
namespace {

constexpr std::uint64_t kGroupExpiryEpochs = 60;

// Standard mode letters, best first.
int standardModeRank(char c) {
    switch (c) {
    case 'R': return 7;
    case 'F': return 6;
    case 'P':
    case 'D': return 5;
    case 'A': return 4;
    case 'E': return 3;
    case 'M': return 2;
    case 'S': return 1;
    default: return 0;
    }
}

} // namespace

int EpochAssembler::modeRank(char c) const {
    const int r = standardModeRank(c);
    // A vendor letter that means a fix ranks with autonomous ('A').
    if (r == 0 && dialect_ && dialect_->modeIndicator &&
        dialect_->modeIndicator(c) != FixType::None)
        return standardModeRank('A');
    return r;
}

// The best of a GNS mode string's per-system letters.
char EpochAssembler::bestMode(std::string_view modes) const {
    char best = 'N';
    for (char c : modes)
        if (modeRank(c) > modeRank(best)) best = c;
    return best;
}

FixType EpochAssembler::fixFromMode(char mode) const {
    if (dialect_ && dialect_->modeIndicator) return dialect_->modeIndicator(mode);
    return fixTypeFromModeIndicator(mode);
}

FixType EpochAssembler::fixFromQuality(int q) const {
    if (dialect_ && dialect_->ggaQuality) return dialect_->ggaQuality(q);
    return fixTypeFromGgaQuality(q);
}

void EpochAssembler::startEpochIfTimeChanged(const std::optional<TimeOfDay> &t,
                                             const Callback &onEpoch) {
    if (!t) return;
    if (current_.time && !(*current_.time == *t)) closeEpoch(onEpoch);
    if (!current_.time) current_.time = t;
}

void EpochAssembler::closeEpoch(const Callback &onEpoch) {
    if (!hasContent_) return;
    Epoch &e = current_;
    if (!e.date) e.date = lastDate_;

    // Fix type: GGA quality, else GNS mode, else RMC mode/status, else GSA; GSA refines 2D/3D.
    if (ggaQuality_) {
        e.fix = fixFromQuality(*ggaQuality_);
    } else if (!gnsMode_.empty()) {
        e.fix = fixFromMode(bestMode(gnsMode_));
    } else if (rmcStatus_ == 'V') {
        e.fix = FixType::None;
    } else if (rmcMode_) {
        e.fix = fixFromMode(*rmcMode_);
    } else if (rmcStatus_ == 'A') {
        e.fix = FixType::Fix3D;
    } else if (gsaFix_) {
        e.fix = *gsaFix_ >= 3 ? FixType::Fix3D : *gsaFix_ == 2 ? FixType::Fix2D : FixType::None;
    }
    if (e.fix == FixType::Fix3D && gsaFix_ == 2) e.fix = FixType::Fix2D;
    if (dialect_ && dialect_->fixNote && e.fix != FixType::None) {
        const char mode = !gnsMode_.empty() ? bestMode(gnsMode_) : rmcMode_.value_or('\0');
        e.fixNote = std::string(dialect_->fixNote(ggaQuality_.value_or(-1), mode));
    }

    // Sky: every committed group, marked with this epoch's used satellites.
    e.satellites.clear();
    for (auto it = groups_.begin(); it != groups_.end();) {
        // A group's parts belong to one epoch: parts still pending now will never complete.
        if (!it->pending.empty() || it->nextIndex > 1) ++incompleteGroups_;
        it->pending.clear();
        it->nextIndex = 0;
        if (epochs_ - it->refreshedEpoch > kGroupExpiryEpochs) {
            it = groups_.erase(it);
            continue;
        }
        // Copied whole, then marked in place: a copy changed on the stack first would be read
        // back from smaller writes than it is read with (a store-forwarding stall per satellite).
        for (const SatelliteInView &sv : it->satellites)
            e.satellites.emplace_back(sv).used = isUsed(sv.sat);
        ++it;
    }
    if (!e.satsUsed && usedThisEpoch_) e.satsUsed = usedCount_;
    // A receiver may send GSA less often than its fix (Nemerix: every 3 s): the DOPs of the last
    // GSA hold until the next one, as the used flags do.
    if (!usedThisEpoch_) {
        if (!e.pdop) e.pdop = lastPdop_;
        if (!e.vdop) e.vdop = lastVdop_;
        if (!e.hdop) e.hdop = lastHdop_;
    }

    onEpoch(e);
    ++epochs_;

    // Start afresh, keeping the satellite list's storage.
    std::vector<SatelliteInView> keep = std::move(current_.satellites);
    keep.clear();
    current_ = Epoch{};
    current_.satellites = std::move(keep);
    hasContent_ = false;
    usedThisEpoch_ = false;
    ggaQuality_.reset();
    gsaFix_.reset();
    rmcMode_.reset();
    rmcStatus_.reset();
    gnsMode_.clear();
}

bool EpochAssembler::sameFuture(const EpochAssembler &o) const {
    if (dialect_ != o.dialect_ || hasContent_ != o.hasContent_ || !(current_ == o.current_) ||
        used_ != o.used_ || usedCount_ != o.usedCount_ || usedThisEpoch_ != o.usedThisEpoch_ ||
        lastPdop_ != o.lastPdop_ || lastHdop_ != o.lastHdop_ || lastVdop_ != o.lastVdop_ ||
        lastDate_ != o.lastDate_ || ggaQuality_ != o.ggaQuality_ || gsaFix_ != o.gsaFix_ ||
        rmcMode_ != o.rmcMode_ || rmcStatus_ != o.rmcStatus_ || gnsMode_ != o.gnsMode_ ||
        groups_.size() != o.groups_.size())
        return false;
    for (std::size_t i = 0; i < groups_.size(); ++i) {
        const GsvGroup &a = groups_[i], &b = o.groups_[i];
        // Only a group's age counts (it expires kGroupExpiryEpochs after its last refresh).
        if (a.key != b.key || a.expectedTotal != b.expectedTotal || a.nextIndex != b.nextIndex ||
            epochs_ - a.refreshedEpoch != o.epochs_ - b.refreshedEpoch ||
            !(a.satellites == b.satellites) || !(a.pending == b.pending))
            return false;
    }
    return true;
}

void EpochAssembler::flush(const Callback &onEpoch) {
    closeEpoch(onEpoch);
}

namespace {

// The order of the sky's groups: GPS, GLONASS, Galileo, BeiDou, QZSS, NavIC, combined, others.
int talkerRank(std::uint32_t key) {
    constexpr std::uint16_t kOrder[] = {'G' << 8 | 'P', 'G' << 8 | 'L', 'G' << 8 | 'A',
                                        'G' << 8 | 'B', 'B' << 8 | 'D', 'G' << 8 | 'Q',
                                        'Q' << 8 | 'Z', 'G' << 8 | 'I', 'G' << 8 | 'N'};
    const auto talker = static_cast<std::uint16_t>(key >> 16);
    for (std::size_t i = 0; i < std::size(kOrder); ++i)
        if (kOrder[i] == talker) return static_cast<int>(i);
    return static_cast<int>(std::size(kOrder));
}

bool groupBefore(std::uint32_t a, std::uint32_t b) {
    const int ra = talkerRank(a), rb = talkerRank(b);
    return ra != rb ? ra < rb : a < b;
}

} // namespace

// Groups are kept in one order, whatever order the receiver first sent them in: a decode started
// anywhere in a log then holds the same sky as one started at its beginning (the log index's
// pieces rely on it to agree with a front-to-back decode).
EpochAssembler::GsvGroup &EpochAssembler::group(std::uint32_t key) {
    // Nearly always a group already known: found by its key alone, the order is looked at only
    // to place a new one.
    for (GsvGroup &g : groups_)
        if (g.key == key) return g;
    auto it = groups_.begin();
    while (it != groups_.end() && !groupBefore(key, it->key)) ++it;
    it = groups_.emplace(it);
    it->key = key;
    it->refreshedEpoch = epochs_;
    return *it;
}

void EpochAssembler::addGsa(const nmea::Gsa &a) {
    if (!usedThisEpoch_) {
        used_.reset();
        usedCount_ = 0;
    }
    usedThisEpoch_ = true;
    for (std::size_t i = 0; i < a.idCount; ++i) {
        if (!isUsed(a.satellites[i])) ++usedCount_;
        markUsed(a.satellites[i]);
    }
    if (a.fix && (!gsaFix_ || *a.fix > *gsaFix_)) gsaFix_ = a.fix;
    if (!current_.pdop) current_.pdop = a.pdop;
    if (!current_.hdop) current_.hdop = a.hdop;
    if (!current_.vdop) current_.vdop = a.vdop;
    if (a.pdop) lastPdop_ = a.pdop;
    if (a.hdop) lastHdop_ = a.hdop;
    if (a.vdop) lastVdop_ = a.vdop;
}

void EpochAssembler::addGsv(const Sentence &s, const nmea::Gsv &gsv) {
    const auto t = s.talker();
    const std::uint32_t key =
            (static_cast<std::uint32_t>(static_cast<unsigned char>(t[0])) << 24) |
            (static_cast<std::uint32_t>(static_cast<unsigned char>(t.size() > 1 ? t[1] : 0))
             << 16) |
            static_cast<std::uint32_t>(gsv.signalId.value_or(0) & 0xFFFF);
    GsvGroup &grp = group(key);
    const int total = gsv.total.value_or(1);
    const int index = gsv.index.value_or(1);
    if (index == 1) {
        if (!grp.pending.empty() || grp.nextIndex > 1) ++incompleteGroups_;
        grp.pending.clear();
        grp.expectedTotal = total;
        grp.nextIndex = 1;
    }
    if (index != grp.nextIndex || total != grp.expectedTotal) {
        // A part is missing or out of order: drop the whole group.
        ++incompleteGroups_;
        grp.pending.clear();
        grp.nextIndex = 0;
    } else {
        for (std::size_t i = 0; i < gsv.satelliteCount; ++i) {
            const nmea::GsvSatellite &sv = gsv.satellites[i];
            SatelliteInView &out = grp.pending.emplace_back(); // filled in place (see above)
            out.sat = sv.sat;
            out.signalId = gsv.signalId.value_or(0);
            out.elevation = sv.elevation;
            out.azimuth = sv.azimuth;
            out.snr = sv.snr;
        }
        if (index == total) {
            grp.satellites.swap(grp.pending);
            grp.pending.clear();
            grp.nextIndex = 0;
            grp.refreshedEpoch = epochs_;
        } else {
            ++grp.nextIndex;
        }
    }
}

void EpochAssembler::add(const Sentence &s, const Message &m, const Callback &onEpoch) {
    using namespace nmea;
    // The sky's sentences first: they are two thirds of a multi-constellation receiver's.
    if (const auto *g = message_cast<Gsv>(m)) {
        addGsv(s, *g);
    } else if (const auto *a = message_cast<Gsa>(m)) {
        addGsa(*a);
    } else if (const auto *g = message_cast<Gga>(m)) {
        startEpochIfTimeChanged(g->time, onEpoch);
        if (g->lat) current_.lat = g->lat;
        if (g->lon) current_.lon = g->lon;
        current_.altMsl = g->altMsl;
        current_.geoidSep = g->geoidSep;
        current_.hdop = g->hdop ? g->hdop : current_.hdop;
        current_.satsUsed = g->satsUsed;
        current_.dgpsAge = g->dgpsAge;
        current_.dgpsStation = g->dgpsStation;
        ggaQuality_ = g->quality;
    } else if (const auto *r = message_cast<Rmc>(m)) {
        startEpochIfTimeChanged(r->time, onEpoch);
        if (!current_.lat && r->lat) current_.lat = r->lat;
        if (!current_.lon && r->lon) current_.lon = r->lon;
        current_.sogKnots = r->sogKnots;
        current_.cog = r->cog;
        if (r->date) current_.date = lastDate_ = r->date;
        rmcMode_ = r->mode;
        rmcStatus_ = r->status;
    } else if (const auto *n = message_cast<Gns>(m)) {
        startEpochIfTimeChanged(n->time, onEpoch);
        // Subsidiary per-system GNS sentences (after a GN one) carry no position: only the
        // main sentence counts.
        if ((n->lat && n->lon) || s.talker() == "GN") {
            if (!current_.lat) current_.lat = n->lat;
            if (!current_.lon) current_.lon = n->lon;
            if (!current_.altMsl) current_.altMsl = n->altMsl;
            if (!current_.geoidSep) current_.geoidSep = n->geoidSep;
            if (!current_.satsUsed) current_.satsUsed = n->satsUsed;
            if (!current_.hdop) current_.hdop = n->hdop;
            gnsMode_ = std::string(n->mode);
        }
    } else if (const auto *l = message_cast<Gll>(m)) {
        startEpochIfTimeChanged(l->time, onEpoch);
        if (!current_.lat && l->lat && l->status != 'V') current_.lat = l->lat;
        if (!current_.lon && l->lon && l->status != 'V') current_.lon = l->lon;
        if (!rmcStatus_ && l->status) rmcStatus_ = l->status;
        if (!rmcMode_ && l->mode) rmcMode_ = l->mode;
    } else if (const auto *z = message_cast<Zda>(m)) {
        startEpochIfTimeChanged(z->time, onEpoch);
        if (z->date) current_.date = lastDate_ = z->date;
    } else if (const auto *v = message_cast<Vtg>(m)) {
        if (!current_.sogKnots) current_.sogKnots = v->sogKnots;
        if (!current_.cog) current_.cog = v->cogTrue;
    } else {
        return; // not an epoch message: nothing to count
    }
    ++current_.sentences;
    hasContent_ = true;
}

} // namespace gnss
