#include "views/console_view.h"
#include "models/refresh_intervals.h"
#include "style/gnss_style.h"

#include "core/sentence_builder.h"
#include "models/console_model.h"

#include <QCompleter>
#include <QHBoxLayout>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QStringListModel>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace gnss::ui {

ConsoleView::ConsoleView(ConsoleModel *model, QWidget *parent) : QWidget(parent), model_(model) {
    setObjectName("console");
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);

    auto *bar = new QHBoxLayout;
    filter_ = new QLineEdit(this);
    filter_->setObjectName("consoleFilter");
    filter_->setPlaceholderText(tr("Filter by address (e.g. GGA|PNVG)"));
    filter_->setClearButtonEnabled(true);
    connect(filter_, &QLineEdit::textChanged, this, &ConsoleView::setFilter);
    bar->addWidget(filter_, 1);
    pause_ = new QToolButton(this);
    pause_->setObjectName("consolePause");
    pause_->setText(tr("Pause"));
    pause_->setCheckable(true);
    connect(pause_, &QToolButton::toggled, this, [this](bool on) { model_->setPaused(on); });
    bar->addWidget(pause_);
    auto *hex = new QToolButton(this);
    hex->setObjectName("consoleHex");
    hex->setText(tr("Hex"));
    hex->setCheckable(true);
    hex->setToolTip(tr("Show the raw bytes received, including binary data"));
    connect(hex, &QToolButton::toggled, this, &ConsoleView::setHex);
    bar->addWidget(hex);
    clear_ = new QToolButton(this);
    clear_->setObjectName("consoleClear");
    clear_->setText(tr("Clear"));
    connect(clear_, &QToolButton::clicked, model_, &ConsoleModel::clear);
    bar->addWidget(clear_);
    // What a log's filter found, beside it: in the bar, so that the console is no taller for it;
    // cut to the room there (the whole text in its tooltip).
    note_ = new QLabel(this);
    note_->setObjectName("consoleNote");
    note_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    note_->setVisible(false);
    bar->insertWidget(1, note_, 1);
    layout->addLayout(bar);

    proxy_ = new QSortFilterProxyModel(this);
    proxy_->setSourceModel(model_);
    proxy_->setFilterRole(ConsoleModel::AddressRole);
    list_ = new QListView(this);
    list_->setObjectName("consoleLines");
    list_->setModel(proxy_);
    list_->setUniformItemSizes(true);
    list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::TypeWriter);
    list_->setFont(mono);
    // Follow new lines unless the user scrolled up to read.
    connect(list_->verticalScrollBar(), &QScrollBar::valueChanged, this,
            [this](int v) { follow_ = v >= list_->verticalScrollBar()->maximum() - 2; });
    connect(proxy_, &QAbstractItemModel::rowsInserted, this, [this] {
        if (follow_ && !logLines_) list_->scrollToBottom();
    });
    connect(list_, &QListView::activated, this, [this](const QModelIndex &i) {
        if (logLines_ && i.isValid()) emit lineActivated(i.row());
    });
    layout->addWidget(list_, 1);

    hex_ = new QPlainTextEdit(this);
    hex_->setObjectName("consoleHexView");
    hex_->setReadOnly(true);
    hex_->setFont(mono);
    hex_->setVisible(false);
    layout->addWidget(hex_, 1);
    auto *hexTimer = new QTimer(this);
    startRefreshTimer(*hexTimer, kTrendRefreshMs, this, [this] {
        if (hex_->isVisible()) refreshHex();
    });

    auto *send = new QHBoxLayout;
    input_ = new QLineEdit(this);
    input_->setObjectName("consoleInput");
    setExample({});
    input_->setFont(mono);
    input_->installEventFilter(this);
    completions_ = new QStringListModel(this);
    auto *completer = new QCompleter(completions_, this);
    completer->setCaseSensitivity(Qt::CaseInsensitive);
    completer->setFilterMode(Qt::MatchContains);
    input_->setCompleter(completer);
    connect(input_, &QLineEdit::returnPressed, this, &ConsoleView::submit);
    send->addWidget(input_, 1);
    sendButton_ = new QPushButton(tr("Send"), this);
    sendButton_->setObjectName("consoleSend");
    connect(sendButton_, &QPushButton::clicked, this, &ConsoleView::submit);
    send->addWidget(sendButton_);
    layout->addLayout(send);
    inputError_ = new QLabel(this);
    inputError_->setObjectName("consoleInputError");
    inputError_->setStyleSheet(style::textColorCss(style::errorColor()));
    inputError_->setVisible(false);
    layout->addWidget(inputError_);
    sendNote_ = new QLabel(this);
    sendNote_->setObjectName("consoleSendNote");
    sendNote_->setWordWrap(true);
    sendNote_->setVisible(false);
    layout->addWidget(sendNote_);
}

void ConsoleView::setSendRefusal(const QString &why) {
    refusal_ = why;
    input_->setEnabled(why.isEmpty());
    sendButton_->setEnabled(why.isEmpty());
    sendButton_->setToolTip(why);
    sendNote_->setText(why.isEmpty() ? QString() : tr("Sending is off: %1.").arg(why));
    sendNote_->setVisible(!why.isEmpty() && !logLines_);
    if (!why.isEmpty()) inputError_->setVisible(false);
    setExample(example_); // the hint says why too
}

void ConsoleView::setCommandNames(const QStringList &names) {
    QStringList withDollar;
    for (const QString &n : names) withDollar << (n.startsWith('$') ? n : '$' + n);
    completions_->setStringList(withDollar);
}

void ConsoleView::setExample(const QString &example) {
    example_ = example;
    if (!refusal_.isEmpty()) {
        input_->setPlaceholderText(tr("No commands: %1").arg(refusal_));
        return;
    }
    input_->setPlaceholderText(
            example.isEmpty()
                    ? tr("Command to send (the checksum is added)")
                    : tr("Command to send, e.g. %1 (the checksum is added)").arg(example));
}

QString ConsoleView::typedCommand() const {
    return input_->text();
}

void ConsoleView::setHistory(const QStringList &history) {
    history_ = history;
}

void ConsoleView::setFilter(const QString &pattern) {
    if (filter_->text() != pattern) filter_->setText(pattern);
    proxy_->setFilterRegularExpression(
            QRegularExpression(pattern, QRegularExpression::CaseInsensitiveOption));
    emit filterChanged(pattern);
}

int ConsoleView::visibleLines() const {
    return logLines_ ? logLines_->rowCount() : proxy_->rowCount();
}

void ConsoleView::showLog(QAbstractItemModel *lines, std::function<QByteArray()> raw) {
    logLines_ = lines;
    logRaw_ = std::move(raw);
    QAbstractItemModel *shown = lines ? lines : static_cast<QAbstractItemModel *>(proxy_);
    if (list_->model() != shown) {
        QItemSelectionModel *previous = list_->selectionModel();
        list_->setModel(shown);
        delete previous; // setModel() leaves the old model's selection to its caller
    }
    // A log is neither paused nor cleared: it is the file; and nothing takes commands.
    pause_->setVisible(!lines);
    clear_->setVisible(!lines);
    input_->setVisible(!lines);
    sendButton_->setVisible(!lines);
    sendNote_->setVisible(!lines && !refusal_.isEmpty());
    if (lines) inputError_->setVisible(false);
    if (!lines) setNote({});
    emit filterChanged(filter_->text());
    follow_ = true;
    if (!lines) list_->scrollToBottom();
    if (hex_->isVisible()) refreshHex();
}

void ConsoleView::showRow(int row) {
    if (!logLines_ || row < 0 || row >= logLines_->rowCount()) return;
    const QModelIndex i = logLines_->index(row, 0);
    list_->selectionModel()->setCurrentIndex(i, QItemSelectionModel::NoUpdate);
    // Like a live console: the cursor's line at the bottom, the lines before it above. A line
    // already in view stays where it is.
    const QRect r = list_->visualRect(i);
    if (!list_->viewport()->rect().contains(r))
        list_->scrollTo(i, QAbstractItemView::PositionAtBottom);
    if (hex_->isVisible()) refreshHex();
}

void ConsoleView::setNote(const QString &note) {
    note_->setText(note);
    note_->setToolTip(note);
    note_->setVisible(!note.isEmpty());
}

bool ConsoleView::submit() {
    const QString typed = input_->text().trimmed();
    if (typed.isEmpty() || !refusal_.isEmpty()) return false;
    std::string error;
    // Checked as gnss-cli send checks it; a wrong checksum is refused, naming the right one.
    const std::string sentence = checkTypedSentence(typed.toStdString(), false, error);
    if (sentence.empty()) {
        showNotSent(QString::fromStdString(error));
        return false;
    }
    inputError_->setVisible(false);
    history_.removeAll(typed);
    history_.append(typed);
    while (history_.size() > 100) history_.removeFirst();
    historyPos_ = -1;
    input_->clear();
    emit sendRequested(QByteArray::fromStdString(sentence));
    return true;
}

void ConsoleView::showNotSent(const QString &why) {
    inputError_->setText(tr("Not sent: %1").arg(why));
    inputError_->setVisible(true);
}

bool ConsoleView::eventFilter(QObject *o, QEvent *e) {
    if (o == input_ && e->type() == QEvent::KeyPress && !history_.isEmpty()) {
        const int key = static_cast<QKeyEvent *>(e)->key();
        if (key == Qt::Key_Up || key == Qt::Key_Down) {
            if (historyPos_ < 0) historyPos_ = int(history_.size());
            historyPos_ =
                    std::clamp(historyPos_ + (key == Qt::Key_Up ? -1 : 1), 0, int(history_.size()));
            input_->setText(historyPos_ < history_.size() ? history_[historyPos_] : QString());
            return true;
        }
    }
    return QWidget::eventFilter(o, e);
}

void ConsoleView::setHex(bool on) {
    list_->setVisible(!on);
    hex_->setVisible(on);
    if (on) refreshHex();
}

void ConsoleView::refreshHex() {
    const QByteArray raw = logLines_ ? (logRaw_ ? logRaw_() : QByteArray()) : model_->raw();
    const QByteArray tail = raw.right(8192);
    QString out;
    out.reserve(tail.size() * 4);
    for (qsizetype i = 0; i < tail.size(); i += 16) {
        const QByteArray row = tail.mid(i, 16);
        out += QStringLiteral("%1  ").arg(i, 6, 16, QChar('0'));
        for (int k = 0; k < 16; ++k)
            out += k < row.size() ? QStringLiteral("%1 ").arg(quint8(row[k]), 2, 16, QChar('0'))
                                  : QStringLiteral("   ");
        out += ' ';
        for (char ch : row) out += (ch >= 0x20 && ch < 0x7F) ? QChar(ch) : QChar('.');
        out += '\n';
    }
    hex_->setPlainText(out);
    hex_->verticalScrollBar()->setValue(hex_->verticalScrollBar()->maximum());
}

} // namespace gnss::ui
