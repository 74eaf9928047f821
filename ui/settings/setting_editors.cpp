#include "settings/setting_editors.h"

#include "config/utf8_text.h"

#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStyle>

#include <cmath>
#include <limits>

namespace gnss::ui {

namespace {

using config::qs;

// An editor whose input is one widget, made here; the subclass sets it up and calls finish().
template <class Input> class InputEditor : public SettingEditor {
public:
    InputEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent)
        : SettingEditor(def, texts, parent), box_(new Input(this)) {}
    QWidget *input() const override { return box_; }

protected:
    Input *box_;
};

class IntegerEditor : public InputEditor<QSpinBox> {
public:
    IntegerEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent)
        : InputEditor(def, texts, parent) {
        box_->setRange(def.min ? static_cast<int>(*def.min) : -999999999,
                       def.max ? static_cast<int>(*def.max) : 999999999);
        box_->setSuffix(unitSuffix());
        box_->setValue(qs(def.defaultValue).toInt());
        editedOn(box_, &QSpinBox::valueChanged);
        finish(box_);
    }
    QString value() const override { return QString::number(box_->value()); }
    void setValue(const QString &v) override {
        bool ok = false;
        const int n = v.trimmed().toInt(&ok);
        if (!ok) return;
        quietly([&] { box_->setValue(n); });
    }
};

class RealEditor : public InputEditor<QDoubleSpinBox> {
public:
    RealEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent)
        : InputEditor(def, texts, parent) {
        box_->setDecimals(4);
        box_->setRange(def.min ? *def.min : -1e9, def.max ? *def.max : 1e9);
        box_->setSingleStep(def.max && def.min && *def.max - *def.min <= 2 ? 0.001 : 0.1);
        box_->setSuffix(unitSuffix());
        box_->setValue(qs(def.defaultValue).toDouble());
        editedOn(box_, &QDoubleSpinBox::valueChanged);
        finish(box_);
    }
    QString value() const override {
        QString s = QString::number(box_->value(), 'f', box_->decimals());
        while (s.contains('.') && (s.endsWith('0') || s.endsWith('.'))) s.chop(1);
        return s;
    }
    void setValue(const QString &v) override {
        bool ok = false;
        const double d = v.trimmed().toDouble(&ok);
        if (!ok) return;
        quietly([&] { box_->setValue(d); });
    }
};

// A combo box as wide as the value it shows (not as its longest option, which can be a sentence:
// "Base station with automatic antenna position averaging"); the list it opens is as wide as
// every option. It never gets less than that width, so the value shown is always whole.
class FittingComboBox : public QComboBox {
public:
    explicit FittingComboBox(QWidget *parent) : QComboBox(parent) {
        setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        setMinimumContentsLength(kMinChars);
        connect(this, &QComboBox::currentIndexChanged, this, [this] { updateGeometry(); });
    }
    QSize sizeHint() const override {
        QSize s = QComboBox::sizeHint(); // kMinChars wide
        const int text = fontMetrics().horizontalAdvance(currentText());
        const int chars = fontMetrics().horizontalAdvance(QLatin1Char('x')) * kMinChars;
        return {s.width() + std::max(0, text - chars), s.height()};
    }
    QSize minimumSizeHint() const override { return sizeHint(); }
    void showPopup() override {
        view()->setMinimumWidth(view()->sizeHintForColumn(0) + 2 * view()->frameWidth() +
                                style()->pixelMetric(QStyle::PM_ScrollBarExtent));
        QComboBox::showPopup();
    }

private:
    static constexpr int kMinChars = 8;
};

class EnumEditor : public InputEditor<FittingComboBox> {
public:
    EnumEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent)
        : InputEditor(def, texts, parent) {
        for (const auto &o : def.options) {
            const QString label = texts(o.label);
            box_->addItem(o.label == o.value ? label : QString("%1 (%2)").arg(label, qs(o.value)),
                          qs(o.value));
        }
        setValue(qs(def.defaultValue));
        editedOn(box_, &QComboBox::currentIndexChanged);
        finish(box_);
    }
    QString value() const override { return box_->currentData().toString(); }
    void setValue(const QString &v) override {
        int i = box_->findData(v.trimmed());
        if (i < 0) // "05" for "5", "on" for "ON"
            for (int k = 0; k < box_->count() && i < 0; ++k) {
                const QString d = box_->itemData(k).toString();
                bool a = false, b = false;
                if (d.compare(v.trimmed(), Qt::CaseInsensitive) == 0 ||
                    (d.toDouble(&a) == v.trimmed().toDouble(&b) && a && b))
                    i = k;
            }
        if (i < 0) return;
        quietly([&] { box_->setCurrentIndex(i); });
    }
};

class BoolEditor : public InputEditor<QCheckBox> {
public:
    BoolEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent)
        : InputEditor(def, texts, parent) {
        // The schema's "on" and "off" values (options when given, else "1"/"0").
        for (const auto &o : def.options) {
            const QString l = qs(o.label).toLower();
            if (l == "on" || l == "1" || l.startsWith("on")) on_ = qs(o.value);
            if (l == "off" || l == "0" || l.startsWith("off")) off_ = qs(o.value);
        }
        setValue(qs(def.defaultValue));
        editedOn(box_, &QCheckBox::toggled);
        finish(box_);
    }
    QString value() const override { return box_->isChecked() ? on_ : off_; }
    void setValue(const QString &v) override {
        const QString l = v.trimmed().toLower();
        bool on;
        if (l == on_.toLower() || l == "1" || l == "on" || l == "true")
            on = true;
        else if (l == off_.toLower() || l == "0" || l == "off" || l == "false")
            on = false;
        else
            return;
        quietly([&] { box_->setChecked(on); });
    }

private:
    QString on_ = "1", off_ = "0";
};

class TextEditor : public InputEditor<QLineEdit> {
public:
    TextEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent)
        : InputEditor(def, texts, parent) {
        box_->setText(qs(def.defaultValue));
        box_->setPlaceholderText(def.type == SettingType::List ? tr("items separated by ';'")
                                                               : QString());
        connect(box_, &QLineEdit::textEdited, this, [this] { emit edited(); });
        finish(box_);
    }
    QString value() const override { return box_->text().trimmed(); }
    void setValue(const QString &v) override { box_->setText(v); }
};

QDoubleSpinBox *coordinateBox(QWidget *parent, double min, double max, int decimals,
                              const QString &suffix) {
    auto *b = new QDoubleSpinBox(parent);
    b->setRange(min, max);
    b->setDecimals(decimals);
    b->setSuffix(suffix);
    return b;
}

// "ddmm.mmmm" / "dddmm.mmmm" → degrees.
double fromNmea(const QString &s) {
    const double v = s.toDouble();
    const double deg = std::floor(v / 100);
    return deg + (v - deg * 100) / 60;
}

// BASEBLH's text: latitude and longitude in radians, height in metres.
QString blhText(const wgs84::Geodetic &g) {
    return QString("%1,%2,%3")
            .arg(wgs84::radians(g.latDeg), 0, 'f', 11)
            .arg(wgs84::radians(g.lonDeg), 0, 'f', 11)
            .arg(g.height, 0, 'f', 4);
}

} // namespace

SettingEditor::SettingEditor(const SettingDef &def, const config::SchemaTexts &texts,
                             QWidget *parent)
    : QWidget(parent), def_(def), texts_(texts) {}

QString SettingEditor::unitSuffix() const {
    return def_.unit.empty() ? QString() : " " + texts_(def_.unit);
}

void SettingEditor::finish(QWidget *input) {
    if (!layout()) {
        auto *l = new QHBoxLayout(this);
        l->setContentsMargins(0, 0, 0, 0);
        l->addWidget(input, 1);
    }
    input->setObjectName(qs(def_.key));
    // Spin boxes and line edits keep the width they ask for (the form wraps or scrolls instead
    // of squeezing them); combo boxes do so by themselves (FittingComboBox).
    if (qobject_cast<QAbstractSpinBox *>(input) || qobject_cast<QLineEdit *>(input))
        input->setMinimumWidth(input->sizeHint().width());
    QString tip = texts_(def_.help);
    if (def_.min || def_.max)
        tip += "\n" + tr("Range: %1 to %2 %3")
                              .arg(def_.min ? QString::number(*def_.min) : QString("-"),
                                   def_.max ? QString::number(*def_.max) : QString("-"),
                                   texts_(def_.unit));
    input->setToolTip(tip.trimmed());
    setFocusProxy(input);
}

CoordinateEditor::CoordinateEditor(const SettingDef &def, const config::SchemaTexts &texts,
                                   Kind kind, QWidget *parent)
    : SettingEditor(def, texts, parent), kind_(kind) {
    // One line per component, so the editor stays narrow enough for a docked form.
    auto *l = new QGridLayout(this);
    l->setContentsMargins(0, 0, 0, 0);
    l->setHorizontalSpacing(4);
    l->setVerticalSpacing(2);
    auto row = [&](int r, const QString &name, QWidget *box, QWidget *extra) {
        auto *label = new QLabel(name, this);
        l->addWidget(label, r, 0);
        l->addWidget(box, r, 1);
        if (extra) l->addWidget(extra, r, 2);
    };
    if (kind == Kind::Ecef) {
        a_ = coordinateBox(this, -1e7, 1e7, 4, tr(" m"));
        b_ = coordinateBox(this, -1e7, 1e7, 4, tr(" m"));
        c_ = coordinateBox(this, -1e7, 1e7, 4, tr(" m"));
        row(0, tr("X"), a_, nullptr);
        row(1, tr("Y"), b_, nullptr);
        row(2, tr("Z"), c_, nullptr);
    } else {
        // Degrees with 8 decimals (about 1 mm) and hemispheres, never a bare minus sign.
        a_ = coordinateBox(this, 0, 90, 8, QStringLiteral("\u00b0"));
        b_ = coordinateBox(this, 0, 180, 8, QStringLiteral("\u00b0"));
        c_ = coordinateBox(this, -1e5, 1e7, 4, tr(" m"));
        c_->setToolTip(tr("Height above the WGS-84 ellipsoid"));
        ns_ = new QComboBox(this);
        ns_->addItems({tr("N"), tr("S")});
        ew_ = new QComboBox(this);
        ew_->addItems({tr("E"), tr("W")});
        row(0, tr("Latitude"), a_, ns_);
        row(1, tr("Longitude"), b_, ew_);
        row(2, tr("Ellipsoidal height"), c_, nullptr);
        for (QComboBox *c : {ns_, ew_}) editedOn(c, &QComboBox::currentIndexChanged);
    }
    convert_ = new QPushButton(this);
    convert_->setObjectName(qs(def.key) + ":convert");
    l->addWidget(convert_, 3, 1, 1, 2, Qt::AlignLeft);
    l->setColumnStretch(3, 1);
    for (QDoubleSpinBox *b : {a_, b_, c_}) editedOn(b, &QDoubleSpinBox::valueChanged);
    finish(a_);
}

QWidget *CoordinateEditor::input() const {
    return a_;
}

QString CoordinateEditor::value() const {
    if (kind_ == Kind::Ecef)
        return QString("%1,%2,%3")
                .arg(a_->value(), 0, 'f', 4)
                .arg(b_->value(), 0, 'f', 4)
                .arg(c_->value(), 0, 'f', 4);
    return blhText(geodetic());
}

void CoordinateEditor::setValue(const QString &value) {
    const QStringList p = value.split(',', Qt::SkipEmptyParts);
    loading_ = true;
    if (kind_ == Kind::Ecef && p.size() == 3) {
        a_->setValue(p[0].toDouble());
        b_->setValue(p[1].toDouble());
        c_->setValue(p[2].toDouble());
    } else if (kind_ == Kind::Geodetic && (p.size() == 3 || p.size() == 5)) {
        wgs84::Geodetic g;
        if (p.size() == 3) { // radians, radians, metres
            g = {wgs84::degrees(p[0].toDouble()), wgs84::degrees(p[1].toDouble()), p[2].toDouble()};
        } else { // ddmm.mmmm,N,dddmm.mmmm,E,H
            g = {fromNmea(p[0]) * (p[1].trimmed() == "S" ? -1 : 1),
                 fromNmea(p[2]) * (p[3].trimmed() == "W" ? -1 : 1), p[4].toDouble()};
        }
        a_->setValue(std::fabs(g.latDeg));
        ns_->setCurrentIndex(g.latDeg < 0 ? 1 : 0);
        b_->setValue(std::fabs(g.lonDeg));
        ew_->setCurrentIndex(g.lonDeg < 0 ? 1 : 0);
        c_->setValue(g.height);
    }
    loading_ = false;
}

wgs84::Geodetic CoordinateEditor::geodetic() const {
    if (kind_ == Kind::Ecef)
        return wgs84::toGeodetic({a_->value(), b_->value(), c_->value()})
                .value_or(wgs84::Geodetic{});
    return {a_->value() * (ns_->currentIndex() == 1 ? -1 : 1),
            b_->value() * (ew_->currentIndex() == 1 ? -1 : 1), c_->value()};
}

void CoordinateEditor::setGeodetic(const wgs84::Geodetic &g) {
    if (kind_ == Kind::Ecef) {
        const wgs84::Ecef e = wgs84::toEcef(g);
        setValue(QString("%1,%2,%3").arg(e.x, 0, 'f', 4).arg(e.y, 0, 'f', 4).arg(e.z, 0, 'f', 4));
    } else {
        setValue(blhText(g));
    }
    emit edited();
}

SettingEditor *makeSettingEditor(const SettingDef &def, const config::SchemaTexts &texts,
                                 QWidget *parent) {
    switch (def.type) {
    case SettingType::Integer: return new IntegerEditor(def, texts, parent);
    case SettingType::Real: return new RealEditor(def, texts, parent);
    case SettingType::Bool: return new BoolEditor(def, texts, parent);
    case SettingType::Enum:
        if (!def.options.empty()) return new EnumEditor(def, texts, parent);
        break;
    case SettingType::Coordinates:
        if (def.key.ends_with("XYZ"))
            return new CoordinateEditor(def, texts, CoordinateEditor::Kind::Ecef, parent);
        if (def.key.ends_with("BLH"))
            return new CoordinateEditor(def, texts, CoordinateEditor::Kind::Geodetic, parent);
        break;
    case SettingType::Text:
    case SettingType::List: break;
    }
    return new TextEditor(def, texts, parent);
}

} // namespace gnss::ui
