#include "logview/log_lines_model.h"

#include "core/framer.h"
#include "core/sentence.h"
#include "logview/log_view.h"
#include "style/gnss_style.h"

#include <QColor>
#include <QGuiApplication>
#include <QPalette>
#include <algorithm>
#include <climits>
#include <string>
#include <unordered_map>

namespace gnss::ui {

using logview::LineRef;
using logview::LineTable;

LogLinesModel::LogLinesModel(QObject *parent)
    : QAbstractListModel(parent), stop_(std::make_shared<std::atomic<bool>>(false)) {}

LogLinesModel::~LogLinesModel() {
    stop_->store(true);
    for (const auto &t : workers_)
        if (t) t->wait();
}

void LogLinesModel::setLog(std::shared_ptr<const logview::LogView> view, LineTime lineTime) {
    stopSearch();
    beginResetModel();
    view_ = std::move(view);
    lineTime_ = std::move(lineTime);
    lines_ = 0;
    base_ = 0;
    matches_ = {};
    cursorBegin_ = cursorEnd_ = 0;
    cursorRow_ = -1;
    endResetModel();
    emit noteChanged(note());
}

void LogLinesModel::setLineCount(std::uint64_t lines) {
    if (!view_ || lines == lines_) return;
    const bool shrunk = lines < lines_;
    if (pattern_.isEmpty()) {
        if (shrunk) {
            beginResetModel();
            lines_ = lines;
            base_ = 0;
            endResetModel();
        } else {
            // A window not yet full takes the new lines; a full one moves with the cursor.
            const int before = rowCount();
            const int after = int(std::min(lines - std::min(base_, lines), kWindow));
            if (after > before) beginInsertRows({}, before, after - 1);
            lines_ = lines;
            if (after > before) endInsertRows();
        }
    } else {
        lines_ = lines;
        if (shrunk) { // a truncated file: what was found may be gone
            stopSearch();
            beginResetModel();
            matches_ = {};
            base_ = 0;
            endResetModel();
        }
        if (searching_)
            searchAgain_ = true;
        else if (!matches_.full)
            search({{}, matches_.scannedTo, false});
    }
    if (const auto at = cursorEnd_ > 0 ? indexOfOffset(cursorEnd_ - 1) : std::nullopt)
        centreOn(*at);
    updateCursorRow();
    emit noteChanged(note());
}

std::uint64_t LogLinesModel::total() const {
    return pattern_.isEmpty() ? lines_ : matches_.offsets.size();
}

std::optional<std::uint64_t> LogLinesModel::indexOfOffset(std::uint64_t offset) const {
    if (!view_ || total() == 0) return std::nullopt;
    if (pattern_.isEmpty()) return std::min(view_->lineAt(offset), lines_ - 1);
    const auto &o = matches_.offsets;
    const auto it = std::upper_bound(o.begin(), o.end(), offset);
    if (it == o.begin()) return std::nullopt;
    return std::uint64_t(it - o.begin()) - 1;
}

bool LogLinesModel::centreOn(std::uint64_t index) {
    const std::uint64_t all = total();
    if (all <= kWindow) {
        if (base_ == 0) return false;
        beginResetModel();
        base_ = 0;
        endResetModel();
        return true;
    }
    if (index >= base_ + kWindow / 4 && index < base_ + kWindow * 3 / 4) return false;
    const std::uint64_t wanted = std::min(index - std::min(index, kWindow / 2), all - kWindow);
    if (wanted == base_) return false;
    beginResetModel();
    base_ = wanted;
    endResetModel();
    emit noteChanged(note());
    return true;
}

void LogLinesModel::setCursor(std::uint64_t begin, std::uint64_t end) {
    const int oldFirst = rowOfOffset(cursorBegin_), oldLast = cursorRow_;
    cursorBegin_ = begin;
    cursorEnd_ = end;
    if (const auto at = end > 0 ? indexOfOffset(end - 1) : std::nullopt; at && centreOn(*at)) {
        cursorRow_ = -2; // the rows are new: announce the cursor's again
        updateCursorRow();
        return;
    }
    updateCursorRow();
    const int first = rowOfOffset(begin);
    const QList<int> roles{Qt::BackgroundRole};
    if (oldLast >= 0) emit dataChanged(index(std::max(0, oldFirst)), index(oldLast), roles);
    if (cursorRow_ >= 0) emit dataChanged(index(std::max(0, first)), index(cursorRow_), roles);
}

void LogLinesModel::updateCursorRow() {
    const int row = cursorEnd_ > 0 ? rowOfOffset(cursorEnd_ - 1) : -1;
    if (row == cursorRow_) return;
    cursorRow_ = row;
    emit cursorRowChanged(row);
}

void LogLinesModel::setFilter(const QString &pattern) {
    if (pattern == pattern_) return;
    stopSearch();
    beginResetModel();
    pattern_ = pattern;
    matches_ = {};
    base_ = 0;
    endResetModel();
    const QRegularExpression re(pattern);
    if (!pattern.isEmpty() && re.isValid() && view_ && lines_ > 0) search({});
    cursorRow_ = -2; // announce the row again, in the new rows
    updateCursorRow();
    emit noteChanged(note());
}

void LogLinesModel::setTimeZone(TimeZoneChoice zone) {
    zone_ = zone;
    if (rowCount() > 0) emit dataChanged(index(0), index(rowCount() - 1), {Qt::DisplayRole});
}

void LogLinesModel::stopSearch() {
    stop_->store(true);
    stop_ = std::make_shared<std::atomic<bool>>(false);
    ++generation_;
    searching_ = searchAgain_ = false;
}

void LogLinesModel::search(LineTable::Matches from) {
    searching_ = true;
    const quint64 generation = generation_;
    const std::size_t limit = kMaxMatches - std::min(kMaxMatches, matches_.offsets.size());
    auto *thread = QThread::create(
            [this, view = view_, stop = stop_, generation, limit,
             re = QRegularExpression(pattern_, QRegularExpression::CaseInsensitiveOption),
             m = std::move(from)]() mutable {
                // A log has a few dozen addresses: each is matched once.
                std::unordered_map<std::string, bool> seen;
                auto keep = [&](std::string_view address) {
                    auto [it, added] = seen.try_emplace(std::string(address), false);
                    if (added)
                        it->second = re.match(QString::fromLatin1(address.data(),
                                                                  qsizetype(address.size())))
                                             .hasMatch();
                    return it->second;
                };
                const bool complete = view->findLines(keep, limit, m, stop.get());
                if (stop->load()) return;
                QMetaObject::invokeMethod(
                        this,
                        [this, generation, m = std::move(m), complete]() mutable {
                            found(generation, std::move(m), complete);
                        },
                        Qt::QueuedConnection);
            });
    connect(thread, &QThread::finished, thread, &QObject::deleteLater);
    std::erase_if(workers_, [](const QPointer<QThread> &t) { return t.isNull(); });
    workers_.emplace_back(thread);
    thread->start(QThread::LowPriority);
    emit noteChanged(note());
}

void LogLinesModel::found(quint64 generation, LineTable::Matches m, bool complete) {
    if (generation != generation_) return;
    searching_ = false;
    if (!m.offsets.empty()) {
        const int before = rowCount();
        const int after = int(std::min<std::uint64_t>(
                matches_.offsets.size() + m.offsets.size() -
                        std::min<std::uint64_t>(base_, matches_.offsets.size() + m.offsets.size()),
                kWindow));
        if (after > before) beginInsertRows({}, before, after - 1);
        matches_.offsets.insert(matches_.offsets.end(), m.offsets.begin(), m.offsets.end());
        if (after > before) endInsertRows();
    }
    if (const auto at = cursorEnd_ > 0 ? indexOfOffset(cursorEnd_ - 1) : std::nullopt)
        centreOn(*at);
    matches_.scannedTo = m.scannedTo;
    matches_.full = m.full || matches_.offsets.size() >= kMaxMatches;
    if (complete && searchAgain_ && !matches_.full) {
        searchAgain_ = false;
        search({{}, matches_.scannedTo, false});
    }
    updateCursorRow();
    emit noteChanged(note());
}

int LogLinesModel::rowCount(const QModelIndex &parent) const {
    if (parent.isValid() || !view_) return 0;
    const std::uint64_t all = total();
    return int(std::min(all - std::min(base_, all), kWindow));
}

std::optional<LineRef> LogLinesModel::lineOfRow(int row) const {
    if (!view_ || row < 0 || row >= rowCount()) return std::nullopt;
    const std::uint64_t index = base_ + std::uint64_t(row);
    if (pattern_.isEmpty()) return view_->line(index);
    const std::uint64_t at = matches_.offsets[std::size_t(index)];
    std::uint64_t next = 0;
    LineRef r = LineTable::lineFrom(view_->bytes(at, Framer::kMaxLine + 1), 0, next);
    r.offset = at;
    return r;
}

int LogLinesModel::rowOfOffset(std::uint64_t offset) const {
    const auto index = indexOfOffset(offset);
    if (!index || *index < base_ || *index >= base_ + std::uint64_t(rowCount())) return -1;
    return int(*index - base_);
}

std::optional<std::uint64_t> LogLinesModel::offsetOfRow(int row) const {
    const auto r = lineOfRow(row);
    return r ? std::optional<std::uint64_t>(r->offset) : std::nullopt;
}

QByteArray LogLinesModel::bytesBeforeCursor(int bytes) const {
    if (!view_ || cursorEnd_ == 0) return {};
    const std::uint64_t from = cursorEnd_ > std::uint64_t(bytes) ? cursorEnd_ - bytes : 0;
    const std::string_view b = view_->bytes(from, cursorEnd_ - from);
    return QByteArray(b.data(), qsizetype(b.size()));
}

QString LogLinesModel::note() const {
    if (!view_) return {};
    if (!pattern_.isEmpty()) {
        const QRegularExpression re(pattern_);
        if (!re.isValid())
            return tr("The filter is not a valid expression: %1").arg(re.errorString());
        if (lines_ == 0 || searching_) return tr("Filtering the log's lines…");
        const int n = int(matches_.offsets.size());
        QString text =
                matches_.full
                        ? tr("The first %L1 lines whose address matches (a filter keeps no more)")
                                  .arg(n)
                        : tr("Lines that match: %L1").arg(n);
        if (std::uint64_t(n) > kWindow)
            text += tr(" · shown: %L1 to %L2, around the cursor")
                            .arg(base_ + 1)
                            .arg(base_ + std::uint64_t(rowCount()));
        return text;
    }
    if (lines_ == 0) return tr("Counting the log's lines…");
    if (lines_ > kWindow)
        return tr("Lines %L1 to %L2 of %L3, around the cursor")
                .arg(base_ + 1)
                .arg(base_ + std::uint64_t(rowCount()))
                .arg(lines_);
    return {};
}

QVariant LogLinesModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid()) return {};
    const auto ref = lineOfRow(index.row());
    if (!ref) return {};
    const std::string_view bytes = view_->bytes(ref->offset, ref->length);
    const auto latin1 = [](std::string_view s) {
        return QString::fromLatin1(s.data(), qsizetype(s.size()));
    };
    switch (role) {
    case Qt::DisplayRole: {
        const qint64 ms = lineTime_ ? lineTime_(ref->offset) : 0;
        return fmt::hostTime(ms, zone_) + QStringLiteral("    ") + latin1(bytes);
    }
    case Qt::BackgroundRole: {
        if (ref->offset < cursorBegin_ || ref->offset >= cursorEnd_) return {};
        QColor c = QGuiApplication::palette().color(QPalette::Highlight);
        c.setAlpha(48);
        return c;
    }
    case ConsoleModel::AddressRole: return latin1(LineTable::addressOf(bytes));
    case ConsoleModel::TimeRole: return lineTime_ ? lineTime_(ref->offset) : 0;
    case ConsoleModel::SentRole: return false;
    default: break;
    }
    if (role != Qt::ForegroundRole && role != Qt::ToolTipRole && role != ConsoleModel::ErrorRole &&
        role != ConsoleModel::ChecksumBadRole)
        return {};
    Sentence s;
    const bool sentence = s.parse(bytes);
    const bool bad = sentence && s.checksum() == ChecksumStatus::Bad;
    const QString error = sentence || bytes.empty() ? QString() : tr("not a sentence");
    const auto hex = [](int v) { return QStringLiteral("%1").arg(v, 2, 16, QChar('0')).toUpper(); };
    switch (role) {
    case Qt::ForegroundRole:
        return bad || !error.isEmpty() ? QVariant(style::errorColor()) : QVariant();
    case Qt::ToolTipRole:
        if (bad)
            return tr("Checksum %1, computed %2")
                    .arg(hex(s.declaredChecksum()), hex(s.computedChecksum()));
        return error.isEmpty() ? QVariant() : QVariant(error);
    case ConsoleModel::ErrorRole: return error;
    case ConsoleModel::ChecksumBadRole: return bad;
    }
    return {};
}

} // namespace gnss::ui
