#pragma once
// One editor per setting, chosen by the schema row's type: a spin box with unit and range
// (integer, real), a combo box (enum), a check box (bool), a coordinate editor (BASEXYZ / BASEBLH:
// X, Y, Z in metres or latitude, longitude with hemispheres and height, converting between the
// two on WGS-84), a line edit otherwise. Every editor reads and writes the schema's value text.
#include "config/schema_texts.h"
#include "core/settings_schema.h"
#include "core/wgs84.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;

namespace gnss::ui {

class SettingEditor : public QWidget {
    Q_OBJECT
public:
    // `texts` translates the row's texts (help, unit, option names) for the dialect.
    SettingEditor(const SettingDef &def, const config::SchemaTexts &texts, QWidget *parent);
    const SettingDef &def() const { return def_; }
    // The value as the schema writes it ("5", "0.05", "GPS", "1", "x,y,z").
    virtual QString value() const = 0;
    // Shows `value` (an empty or unreadable value leaves the editor as it is). Emits nothing.
    virtual void setValue(const QString &value) = 0;
    // The widget that takes focus and edits (for tests: its objectName is the key).
    virtual QWidget *input() const = 0;

signals:
    void edited(); // the user changed the value

protected:
    void finish(QWidget *input); // layout, tooltip, object name, change signal
    QString unitSuffix() const;  // " Hz", translated; empty when none
    const config::SchemaTexts &texts() const { return texts_; }
    // edited() when `input` sends `changed`, but not while a value is shown (quietly()).
    template <class Input, class Signal> void editedOn(Input *input, Signal changed) {
        connect(input, changed, this, [this] {
            if (!loading_) emit edited();
        });
    }
    // Shows a value through `set` without emitting edited().
    template <class Set> void quietly(Set set) {
        loading_ = true;
        set();
        loading_ = false;
    }
    bool loading_ = false;

private:
    SettingDef def_;
    config::SchemaTexts texts_;
};

// The editor for a schema row.
SettingEditor *makeSettingEditor(const SettingDef &def, const config::SchemaTexts &texts,
                                 QWidget *parent);

// BASEXYZ / BASEBLH.
class CoordinateEditor : public SettingEditor {
    Q_OBJECT
public:
    enum class Kind { Ecef, Geodetic };
    CoordinateEditor(const SettingDef &def, const config::SchemaTexts &texts, Kind kind,
                     QWidget *parent);
    Kind kind() const { return kind_; }
    QString value() const override;
    void setValue(const QString &value) override;
    QWidget *input() const override;

    wgs84::Geodetic geodetic() const;
    void setGeodetic(const wgs84::Geodetic &g); // the user's edit: emits edited()
    // The button that fills this editor from the other form ("From BASEXYZ").
    QPushButton *convertButton() const { return convert_; }

private:
    Kind kind_;
    QDoubleSpinBox *a_, *b_, *c_;
    QComboBox *ns_ = nullptr, *ew_ = nullptr;
    QPushButton *convert_;
};

} // namespace gnss::ui
