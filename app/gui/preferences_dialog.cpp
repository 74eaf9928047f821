#include "gui/preferences_dialog.h"
#include "style/gnss_style.h"

#include <QComboBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace gnss::app {

namespace {

void select(QComboBox *box, const QVariant &data) {
    const int i = box->findData(data);
    box->setCurrentIndex(i >= 0 ? i : 0);
}

} // namespace

PreferencesDialog::PreferencesDialog(const Preferences &prefs, const QString &runningLanguage,
                                     QWidget *parent)
    : QDialog(parent), runningLanguage_(runningLanguage) {
    setObjectName("preferencesDialog");
    setWindowTitle(tr("Preferences"));
    auto *outer = new QVBoxLayout(this);
    // The dialog follows its content: a note or an error shown makes it taller, never clipped.
    outer->setSizeConstraint(QLayout::SetFixedSize);
    auto *form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    outer->addLayout(form);

    language_ = new QComboBox(this);
    language_->setObjectName("prefLanguage");
    const QString system = QLocale::system().nativeLanguageName();
    language_->addItem(tr("System (%1)").arg(system), "system");
    language_->addItem(QStringLiteral("English"), "en"); // each language in its own name
    language_->addItem(QStringLiteral("Русский"), "ru");
    form->addRow(tr("&Language:"), language_);
    languageNote_ = new QLabel(tr("The new language is used from the next start of GNSS "
                                  "Workbench."),
                               this);
    languageNote_->setObjectName("prefLanguageNote");
    languageNote_->setForegroundRole(QPalette::PlaceholderText);
    form->addRow(QString(), languageNote_);

    theme_ = new QComboBox(this);
    theme_->setObjectName("prefTheme");
    theme_->addItem(tr("Follow the system"), "system");
    theme_->addItem(tr("Light"), "light");
    theme_->addItem(tr("Dark"), "dark");
    form->addRow(tr("&Theme:"), theme_);

    units_ = new QComboBox(this);
    units_->setObjectName("prefUnits");
    units_->addItem(tr("Metric (m, m/s, km)"), int(ui::UnitSystem::Metric));
    units_->addItem(tr("Imperial (ft, mph, mi)"), int(ui::UnitSystem::Imperial));
    units_->addItem(tr("Nautical (m, kn, NM)"), int(ui::UnitSystem::Nautical));
    form->addRow(tr("&Units:"), units_);

    coordinates_ = new QComboBox(this);
    coordinates_->setObjectName("prefCoordinates");
    const double example = 55.843382467;
    for (auto f : {ui::CoordinateFormat::Degrees, ui::CoordinateFormat::DegreesMinutes,
                   ui::CoordinateFormat::DegreesMinutesSeconds})
        coordinates_->addItem(ui::fmt::latitude(example, f), int(f));
    form->addRow(tr("&Coordinates:"), coordinates_);

    time_ = new QComboBox(this);
    time_->setObjectName("prefTime");
    time_->addItem(tr("UTC"), int(ui::TimeZoneChoice::Utc));
    time_->addItem(tr("Local time (%1)")
                           .arg(ui::fmt::utcOffset(QDateTime::currentDateTime().offsetFromUtc())),
                   int(ui::TimeZoneChoice::Local));
    form->addRow(tr("T&ime:"), time_);

    bauds_ = new QLineEdit(this);
    bauds_->setObjectName("prefBauds");
    bauds_->setToolTip(tr("The serial speeds baud \"auto\" tries, in this order, separated by "
                          "commas"));
    // Wide enough for the whole built-in list: the order is the point, none of it scrolled away.
    bauds_->setMinimumWidth(
            bauds_->fontMetrics().horizontalAdvance(baudListText(defaultDetectionBauds())) + 24);
    form->addRow(tr("&Baud rates to try:"), bauds_);
    baudError_ = new QLabel(this);
    baudError_->setObjectName("prefBaudError");
    baudError_->setStyleSheet(style::textColorCss(style::errorColor()));
    form->addRow(QString(), baudError_);

    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                            QDialogButtonBox::RestoreDefaults,
                                    this);
    outer->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons_->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] { setPreferences(Preferences{}); });
    connect(language_, &QComboBox::currentIndexChanged, this, &PreferencesDialog::validate);
    connect(bauds_, &QLineEdit::textChanged, this, &PreferencesDialog::validate);
    setPreferences(prefs);
}

void PreferencesDialog::setPreferences(const Preferences &p) {
    select(language_, p.language);
    select(theme_, p.theme);
    select(units_, int(p.display.units));
    select(coordinates_, int(p.display.coordinates));
    select(time_, int(p.display.time));
    bauds_->setText(
            baudListText(p.detectionBauds.isEmpty() ? defaultDetectionBauds() : p.detectionBauds));
    validate();
}

Preferences PreferencesDialog::preferences() const {
    Preferences p;
    p.language = language_->currentData().toString();
    p.theme = theme_->currentData().toString();
    p.display.units = ui::UnitSystem(units_->currentData().toInt());
    p.display.coordinates = ui::CoordinateFormat(coordinates_->currentData().toInt());
    p.display.time = ui::TimeZoneChoice(time_->currentData().toInt());
    QString ignored;
    p.detectionBauds = parseBaudList(bauds_->text(), &ignored);
    return p;
}

void PreferencesDialog::validate() {
    languageNote_->setVisible(language_->currentData().toString() != runningLanguage_);
    QString why;
    const bool ok = !parseBaudList(bauds_->text(), &why).isEmpty();
    baudError_->setText(ok ? QString() : why);
    baudError_->setVisible(!ok);
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(ok);
}

} // namespace gnss::app
