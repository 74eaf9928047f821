#pragma once
// The Preferences dialog (Edit → Preferences…): language, theme, units, coordinate format, time
// zone and the baud rates "auto" tries. It edits a copy; the caller applies what it returns.
#include "gui/preferences.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace gnss::app {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    // `runningLanguage`: the language preference the program started with (a change of language
    // takes effect at the next start, and the dialog says so).
    PreferencesDialog(const Preferences &prefs, const QString &runningLanguage,
                      QWidget *parent = nullptr);
    // What the dialog shows now (valid when accepted).
    Preferences preferences() const;
    void setPreferences(const Preferences &prefs);

private:
    void validate();
    QString runningLanguage_;
    QComboBox *language_, *theme_, *units_, *coordinates_, *time_;
    QLineEdit *bauds_;
    QLabel *languageNote_, *baudError_;
    QDialogButtonBox *buttons_;
};

} // namespace gnss::app
