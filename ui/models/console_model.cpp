#include "models/console_model.h"
#include "style/gnss_style.h"

#include <QColor>

namespace gnss::ui {
namespace {
constexpr int kMaxRaw = 64 * 1024;
}

ConsoleModel::ConsoleModel(QObject *parent) : QAbstractListModel(parent) {}

int ConsoleModel::rowCount(const QModelIndex &p) const {
    return p.isValid() ? 0 : int(lines_.size());
}

QVariant ConsoleModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= int(lines_.size())) return {};
    const ConsoleLine &l = lines_[size_t(index.row())];
    switch (role) {
    case Qt::DisplayRole: {
        // The host's clock when the line arrived, in the zone the user chose.
        const QString time = fmt::hostTime(l.ms, zone_);
        return time + (l.sent ? QStringLiteral("  ▶ ") : QStringLiteral("    ")) +
               QString::fromLatin1(l.text);
    }
    case Qt::ToolTipRole:
        if (!l.error.isEmpty()) return l.error;
        return l.note.isEmpty() ? QVariant() : QVariant(l.note);
    case Qt::ForegroundRole:
        if (l.checksumBad || !l.error.isEmpty()) return style::errorColor();
        if (l.sent) return style::sentColor();
        return {};
    case SentRole: return l.sent;
    case ChecksumBadRole: return l.checksumBad;
    case ErrorRole: return l.error;
    case AddressRole: return QString::fromLatin1(l.address);
    case TimeRole: return l.ms;
    }
    return {};
}

void ConsoleModel::append(ConsoleLine line) {
    // Drop a quarter of the cap at once (amortised), keeping the newest kMaxLines - 1.
    if (pending_.size() >= std::size_t(kMaxPending))
        pending_.erase(pending_.begin(), pending_.end() - (kMaxLines - 1));
    pending_.push_back(std::move(line));
}

void ConsoleModel::flush() {
    if (pending_.empty()) return;
    if (paused_) {
        // Paused: keep only what fits, so resuming shows the latest lines.
        if (pending_.size() > size_t(kMaxLines))
            pending_.erase(pending_.begin(), pending_.end() - kMaxLines);
        return;
    }
    const int overflow = int(lines_.size() + pending_.size()) - kMaxLines;
    if (overflow > 0) {
        const int drop = std::min(overflow, int(lines_.size()));
        if (drop > 0) {
            beginRemoveRows({}, 0, drop - 1);
            lines_.erase(lines_.begin(), lines_.begin() + drop);
            endRemoveRows();
        }
        if (pending_.size() > size_t(kMaxLines))
            pending_.erase(pending_.begin(), pending_.end() - kMaxLines);
    }
    const std::size_t moved = pending_.size();
    beginInsertRows({}, int(lines_.size()), int(lines_.size() + pending_.size()) - 1);
    for (auto &l : pending_) lines_.push_back(std::move(l));
    endInsertRows();
    pending_.clear();
    // A burst's room goes back once the bursts are over (a flush that used a quarter of it): at
    // 20 Hz a flush moves a few hundred lines, and a vector keeps its largest size (up to 3.6 MB
    // after a burst of kMaxPending lines), while lines that keep coming fast keep their room.
    constexpr std::size_t kKeep = 4096;
    if (pending_.capacity() > kKeep && moved < pending_.capacity() / 4)
        std::vector<ConsoleLine>().swap(pending_);
}

void ConsoleModel::clear() {
    beginResetModel();
    lines_.clear();
    pending_.clear();
    raw_.clear();
    endResetModel();
}

void ConsoleModel::appendRaw(const QByteArray &bytes) {
    raw_.append(bytes);
    if (raw_.size() > kMaxRaw) raw_.remove(0, raw_.size() - kMaxRaw);
}

} // namespace gnss::ui
