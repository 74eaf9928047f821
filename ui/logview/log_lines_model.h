#pragma once
// LogLinesModel: the console's rows while a log is open: the file's lines, read from the mapping
// when a row is drawn (nothing is copied), or, with a filter, the lines whose address matches it
// (found on a worker thread over the whole log, at most kMaxMatches of them). The rows are a
// window of kWindow lines around the cursor, moved as the cursor moves: a list view lays out and
// keeps a position for every row it is given, which for the 15 million lines of a 1 GB log would
// cost it seconds and a hundred megabytes. The lines of the cursor's epoch are marked.
//
// Rows have the live console's roles (ConsoleModel::Role), so the same view shows both.
#include "models/console_model.h"

#include <QAbstractListModel>
#include <QPointer>
#include <QRegularExpression>
#include <QThread>
#include <atomic>
#include <functional>
#include <memory>

#include "logview/line_table.h"

namespace gnss::logview {
class LogView;
}

namespace gnss::ui {

class LogLinesModel : public QAbstractListModel {
    Q_OBJECT
public:
    // Offsets kept for a filter: 8 bytes each, 32 MB at most.
    static constexpr std::size_t kMaxMatches = 4'000'000;
    // Rows shown at once: the lines around the cursor (the live console keeps as many).
    static constexpr std::uint64_t kWindow = 20'000;
    // A line's time (host or UTC, ms) from its file offset.
    using LineTime = std::function<qint64(std::uint64_t offset)>;

    explicit LogLinesModel(QObject *parent = nullptr);
    ~LogLinesModel() override; // stops and joins a filter search

    // The open log (nullptr: none); its lines appear once setLineCount() says how many there are.
    void setLog(std::shared_ptr<const logview::LogView> view, LineTime lineTime);
    // The log's lines were counted (LogView::indexLines on a worker): rows are added, and a
    // filter goes on over what a followed file gained.
    void setLineCount(std::uint64_t lines);
    // The cursor's epoch: the bytes [begin, end) of the file. Its lines are marked, and
    // cursorRowChanged() names the row of its last line (or of the last match before it).
    void setCursor(std::uint64_t begin, std::uint64_t end);
    int cursorRow() const { return cursorRow_; }
    // Only the lines whose address matches `pattern` (case-insensitive regular expression, as the
    // live console's filter); empty: every line.
    void setFilter(const QString &pattern);
    bool filtering() const { return searching_; }
    void setTimeZone(TimeZoneChoice zone);

    // The file offset of a row's line (for a click: the epoch holding it).
    std::optional<std::uint64_t> offsetOfRow(int row) const;
    // The file's bytes up to the end of the cursor's epoch, at most `bytes` of them (hex view).
    QByteArray bytesBeforeCursor(int bytes) const;
    // What the filter found, or that it is still looking (for a line above the list).
    QString note() const;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;

signals:
    void cursorRowChanged(int row);
    void noteChanged(const QString &note);

private:
    std::optional<logview::LineRef> lineOfRow(int row) const;
    int rowOfOffset(std::uint64_t offset) const;
    // Lines (or matches) in all, and the one holding an offset, counted from the first.
    std::uint64_t total() const;
    std::optional<std::uint64_t> indexOfOffset(std::uint64_t offset) const;
    // Moves the window so that `index` is in its middle half; true when it moved.
    bool centreOn(std::uint64_t index);
    void search(logview::LineTable::Matches from);
    void found(quint64 generation, logview::LineTable::Matches m, bool complete);
    void stopSearch();
    void updateCursorRow();

    std::shared_ptr<const logview::LogView> view_;
    LineTime lineTime_;
    std::uint64_t lines_ = 0; // counted
    std::uint64_t base_ = 0;  // the first row's line (or match)
    QString pattern_;
    logview::LineTable::Matches matches_; // with a filter
    bool searching_ = false, searchAgain_ = false;
    quint64 generation_ = 0;
    std::shared_ptr<std::atomic<bool>> stop_;
    std::vector<QPointer<QThread>> workers_;
    std::uint64_t cursorBegin_ = 0, cursorEnd_ = 0;
    int cursorRow_ = -1;
    TimeZoneChoice zone_ = TimeZoneChoice::Utc;
};

} // namespace gnss::ui
