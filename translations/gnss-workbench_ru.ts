<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru" sourcelanguage="en">
<context>
    <name>Constellation</name>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="+37"/>
        <source>unknown system</source>
        <translation>неизвестная система</translation>
    </message>
</context>
<context>
    <name>FixType</name>
    <message>
        <location line="+6"/>
        <source>No fix</source>
        <translation>Нет решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Estimated</source>
        <translation>Счисление</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DGNSS</source>
        <translation>DGNSS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK float</source>
        <translation>RTK float</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK fixed</source>
        <translation>RTK fixed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed position</source>
        <translation>Фиксированные координаты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulator</source>
        <translation>Симулятор</translation>
    </message>
</context>
<context>
    <name>Hemisphere</name>
    <message>
        <location filename="../ui/models/value_format.cpp" line="+114"/>
        <source>N</source>
        <translation>с. ш.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S</source>
        <translation>ю. ш.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>E</source>
        <translation>в. д.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>W</source>
        <translation>з. д.</translation>
    </message>
</context>
<context>
    <name>Preferences</name>
    <message>
        <location filename="../app/gui/preferences.cpp" line="+55"/>
        <source>&apos;%1&apos; is not a serial port speed</source>
        <translation>«%1» — не скорость последовательного порта</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is listed twice</source>
        <translation>%1 указана дважды</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>List at least one speed</source>
        <translation>Укажите хотя бы одну скорость</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/cli/settings_link.cpp" line="+68"/>
        <source>reading the settings failed: %1</source>
        <translation>не удалось прочитать настройки: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n command(s) failed</source>
        <translation>
            <numerusform>%n команда завершилась с ошибкой</numerusform>
            <numerusform>%n команды завершились с ошибкой</numerusform>
            <numerusform>%n команд завершились с ошибкой</numerusform>
        </translation>
    </message>
    <message>
        <location line="+27"/>
        <source>unknown dialect &apos;%1&apos;</source>
        <translation>неизвестный диалект «%1»</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the receiver&apos;s dialect was not recognised (%1); give --dialect</source>
        <translation>диалект приёмника не распознан (%1); укажите --dialect</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the %1 dialect has no settings</source>
        <translation>у диалекта %1 нет настроек</translation>
    </message>
    <message>
        <location filename="../app/cli/cmd_config.cpp" line="+95"/>
        <source>config needs an action: get, set, export, apply, diff or action</source>
        <translation>для config нужно действие: get, set, export, apply, diff или action</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>set expects KEY=VALUE, got &apos;%1&apos;</source>
        <translation>set ожидает КЛЮЧ=ЗНАЧЕНИЕ, получено «%1»</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>set needs at least one KEY=VALUE</source>
        <translation>для set нужна хотя бы одна пара КЛЮЧ=ЗНАЧЕНИЕ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>config %1 needs one FILE</source>
        <translation>для config %1 нужен один ФАЙЛ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>config action needs one of save, defaults, cold, warm, hot</source>
        <translation>для config action нужно одно из: save, defaults, cold, warm, hot</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown config action &apos;%1&apos;: get, set, export, apply, diff or action</source>
        <translation>неизвестное действие config «%1»: get, set, export, apply, diff или action</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>unknown action &apos;%1&apos;: save, defaults, cold, warm or hot</source>
        <translation>неизвестное действие «%1»: save, defaults, cold, warm или hot</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%n setting(s) of the %1 receiver written to %2</source>
        <translation>
            <numerusform>%n настройка приёмника %1 записана в %2</numerusform>
            <numerusform>%n настройки приёмника %1 записаны в %2</numerusform>
            <numerusform>%n настроек приёмника %1 записано в %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+45"/>
        <source>%n setting(s) of the receiver differ from %1</source>
        <translation>
            <numerusform>%n настройка приёмника отличается от %1</numerusform>
            <numerusform>%n настройки приёмника отличаются от %1</numerusform>
            <numerusform>%n настроек приёмника отличаются от %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../protocol/config/settings_profile.cpp" line="+48"/>
        <source>not a settings profile: %1</source>
        <translation>это не профиль настроек: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a settings profile (format is &apos;%1&apos;, expected &apos;%2&apos;)</source>
        <translation>это не профиль настроек (формат «%1», ожидался «%2»)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>profile version %1 is not supported (this program reads version 1 to %2)</source>
        <translation>версия профиля %1 не поддерживается (программа читает версии от 1 до %2)</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>the profile is for dialect &apos;%1&apos;, the receiver speaks &apos;%2&apos;</source>
        <translation>профиль предназначен для диалекта «%1», а приёмник использует «%2»</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>%1: the value must be a string</source>
        <translation>%1: значение должно быть строкой</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: given twice (as %2 and %3)</source>
        <translation>%1: задано дважды (как %2 и %3)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the profile names settings the %1 dialect cannot set: %2</source>
        <translation>профиль содержит настройки, которые диалект %1 не может задать: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the profile is for the %1, the receiver is a %2: export a profile from a %2, or edit the file&apos;s &quot;model&quot; if the settings suit it</source>
        <translation>профиль для %1, а приёмник — %2: экспортируйте профиль из %2 или исправьте «model» в файле, если настройки ему подходят</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>cannot write %1: %2</source>
        <translation>не удаётся записать %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/cmd_config.cpp" line="-36"/>
        <location filename="../protocol/config/settings_profile.cpp" line="+9"/>
        <source>cannot read %1: %2</source>
        <translation>не удаётся прочитать %1: %2</translation>
    </message>
</context>
<context>
    <name>Refusal</name>
    <message>
        <location filename="../protocol/core/settings_schema.cpp" line="+155"/>
        <location filename="../protocol/geostar/geostar_encode_util.cpp" line="+11"/>
        <location filename="../protocol/geostar/geostar_status_words.cpp" line="+61"/>
        <location filename="../protocol/nemerix/nemerix_ephemeris.cpp" line="+78"/>
        <location line="+57"/>
        <location line="+6"/>
        <location filename="../protocol/nemerix/nemerix_hex.cpp" line="+83"/>
        <location line="+33"/>
        <location filename="../protocol/nemerix/nemerix_iono_utc.cpp" line="+58"/>
        <location line="+73"/>
        <location filename="../protocol/nemerix/nemerix_settings_report.cpp" line="+136"/>
        <location filename="../protocol/nvs/nvs_output_fields.cpp" line="+26"/>
        <source>%1: %2 is out of range; accepted: %3</source>
        <translation>%1: %2 вне допустимого диапазона; допустимо: %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../protocol/nemerix/nemerix_hex.cpp" line="-30"/>
        <source>%1: %2 is out of range; accepted: %3 %4</source>
        <translation>%1: %2 вне допустимого диапазона; допустимо: %3 %4</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>the command would be %1 characters long; the receiver takes at most %2</source>
        <translation>команда получилась бы длиной %1 символов; приёмник принимает не более %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <location filename="../protocol/geostar/geostar_encode_util.cpp" line="+18"/>
        <source>%1: the value is %2 characters long; at most %3</source>
        <translation>%1: значение длиной %2 символов; допустимо не более %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../protocol/geostar/geostar_encode_util.cpp" line="+6"/>
        <location filename="../protocol/nemerix/nemerix_prefix.cpp" line="+37"/>
        <location filename="../protocol/nvs/nvs_output_fields.cpp" line="+94"/>
        <source>%1: character not allowed in a value: &apos;%2&apos;</source>
        <translation>%1: недопустимый символ в значении: «%2»</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: expected 0 or 1, got &apos;%2&apos;</source>
        <translation>%1: ожидается 0 или 1, получено «%2»</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../protocol/nemerix/nemerix_settings_values.cpp" line="+179"/>
        <location filename="../protocol/nvs/nvs_idl.cpp" line="+159"/>
        <location filename="../protocol/nvs/nvs_tst.cpp" line="+57"/>
        <source>%1: expected an integer, got &apos;%2&apos;</source>
        <translation>%1: ожидается целое число, получено «%2»</translation>
    </message>
    <message>
        <location line="+7"/>
        <location filename="../protocol/nemerix/nemerix_hex.cpp" line="-11"/>
        <location filename="../protocol/nemerix/nemerix_settings_values.cpp" line="+6"/>
        <location filename="../protocol/nvs/nvs_output_fields.cpp" line="-47"/>
        <source>%1: expected a number, got &apos;%2&apos;</source>
        <translation>%1: ожидается число, получено «%2»</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../protocol/geostar/geostar_encode_util.cpp" line="-19"/>
        <location filename="../protocol/nvs/nvs_idl.cpp" line="-13"/>
        <location filename="../protocol/nvs/nvs_output_fields.cpp" line="+32"/>
        <location filename="../protocol/nvs/nvs_timemark.cpp" line="+62"/>
        <source>%1: &apos;%2&apos; is not one of: %3</source>
        <translation>%1: «%2» не входит в список: %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: expected numbers separated by &apos;,&apos;, got &apos;%2&apos;</source>
        <translation>%1: ожидаются числа через «,», получено «%2»</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: &apos;,&apos; is not allowed in this value</source>
        <translation>%1: символ «,» в этом значении недопустим</translation>
    </message>
    <message>
        <location filename="../protocol/geostar/geostar_schema.cpp" line="+60"/>
        <source>%1: &apos;%2&apos; is reported by the receiver but cannot be set with an NMEA command</source>
        <translation>%1: значение «%2» приёмник сообщает, но установить его командой NMEA нельзя</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_settings.cpp" line="+90"/>
        <location filename="../protocol/nemerix/nemerix_settings_values.cpp" line="+64"/>
        <source>fix.timeZone: &apos;%1&apos; is not accepted; accepted: h:m with hours -13..13 and minutes 0..59</source>
        <translation>fix.timeZone: «%1» недопустимо; допустимо: ч:м, часы -13..13, минуты 0..59</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>fix.timeZone: &apos;%1&apos; is UTC itself: write 0:0</source>
        <translation>fix.timeZone: «%1» — это и есть UTC: пишите 0:0</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>datum.mapDatum: %1 is out of range; accepted: 0..218 (internal table) or 500 (user defined)</source>
        <translation>datum.mapDatum: %1 вне допустимого диапазона; допустимо: 0..218 (встроенная таблица) или 500 (задаётся пользователем)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>datum.mapDatum: required with any datum.* setting; accepted: 0..218 or 500</source>
        <translation>datum.mapDatum: обязательна вместе с любой настройкой datum.*; допустимо: 0..218 или 500</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>power.offPeriod: only used with power.mode=1 (LDCM1)</source>
        <translation>power.offPeriod: используется только при power.mode=1 (LDCM1)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>serial.baud: required with serial.protocol / serial.parity (PNMRX100 sends all three); accepted: %1</source>
        <translation>serial.baud: обязательна вместе с serial.protocol / serial.parity (PNMRX100 передаёт все три); допустимо: %1</translation>
    </message>
    <message>
        <location filename="../protocol/nvs/nvs_encode_util.cpp" line="+8"/>
        <source>unknown setting &apos;%1&apos;</source>
        <translation>неизвестная настройка «%1»</translation>
    </message>
    <message>
        <location filename="../protocol/nvs/nvs_rtk.cpp" line="+100"/>
        <source>PNVGRTK: unknown parameter &apos;%1&apos; (Table 4: MODE, PVTRATE, ... INITGPSWEEK)</source>
        <translation>PNVGRTK: неизвестный параметр «%1» (таблица 4: MODE, PVTRATE, ... INITGPSWEEK)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rtk.%1: a value is required (an empty value is a query)</source>
        <translation>rtk.%1: нужно значение (пустое значение — это запрос)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>a value before any parameter name</source>
        <translation>значение перед именем параметра</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>PNVGRTK names no parameter</source>
        <translation>в PNVGRTK не назван ни один параметр</translation>
    </message>
    <message>
        <location filename="../protocol/nvs/nvs_settings.cpp" line="+43"/>
        <source>%1: &apos;%2&apos; is not ADDRESS:RATE (rate in PVT intervals, &gt;= 1)</source>
        <translation>%1: «%2» не в виде АДРЕС:ТЕМП (темп в интервалах PVT, &gt;= 1)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>idl.stations: &apos;%1&apos; is not ID:ICB</source>
        <translation>idl.stations: «%1» не в виде ID:ICB</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>idl.stations: station %1 is listed twice</source>
        <translation>idl.stations: станция %1 указана дважды</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>idl.stations: %1 stations is out of range; accepted: 0..32 stations</source>
        <translation>idl.stations: число станций %1 вне допустимого диапазона; допустимо: 0..32</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>PNVGNME sets time and position decimals together: give %1 too</source>
        <translation>PNVGNME задаёт число знаков времени и координат вместе: укажите также %1</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>PNVGRZA sets baud rate and protocol together: give %1 too</source>
        <translation>PNVGRZA задаёт скорость и протокол вместе: укажите также %1</translation>
    </message>
    <message>
        <location filename="../protocol/core/field_reader.cpp" line="+32"/>
        <location filename="../protocol/geostar/geostar_encode_util.cpp" line="+6"/>
        <source>field %1 (%2): %3: &apos;%4&apos;</source>
        <translation>поле %1 (%2): %3: «%4»</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>expected at least %1 fields, got %2</source>
        <translation>ожидается не менее %1 полей, получено %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not an integer</source>
        <translation>не целое число</translation>
    </message>
    <message>
        <location line="+7"/>
        <location filename="../protocol/nemerix/nemerix_fix_settings.cpp" line="+108"/>
        <location filename="../protocol/nemerix/nemerix_nav_init.cpp" line="+43"/>
        <location line="+2"/>
        <location filename="../protocol/nmea/gsv.cpp" line="+43"/>
        <location line="+2"/>
        <location line="+18"/>
        <location line="+2"/>
        <location filename="../protocol/nmea/zda.cpp" line="+18"/>
        <location line="+2"/>
        <source>out of range</source>
        <translation>вне допустимого диапазона</translation>
    </message>
    <message>
        <location line="+7"/>
        <location filename="../protocol/nemerix/nemerix_hex.cpp" line="-60"/>
        <source>not hexadecimal</source>
        <translation>не шестнадцатеричное число</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>expected one character</source>
        <translation>ожидается один символ</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not a ddmm.mmmm coordinate</source>
        <translation>не координата вида ддмм.мммм</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bad hemisphere</source>
        <translation>неверное полушарие</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>not an hhmmss.ss time</source>
        <translation>не время вида ччммсс.сс</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a ddmmyy date</source>
        <translation>не дата вида ддммгг</translation>
    </message>
    <message>
        <location filename="../protocol/core/field_reader.h" line="+30"/>
        <source>not a number</source>
        <translation>не число</translation>
    </message>
    <message>
        <location filename="../protocol/core/sentence.cpp" line="+73"/>
        <source>not a sentence</source>
        <translation>не сообщение NMEA</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>sentence too long</source>
        <translation>слишком длинное сообщение</translation>
    </message>
    <message>
        <location line="+92"/>
        <location filename="../protocol/nemerix/nemerix_fields.cpp" line="+25"/>
        <source>too many fields</source>
        <translation>слишком много полей</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>empty address</source>
        <translation>пустой адрес</translation>
    </message>
    <message>
        <location filename="../protocol/core/stream_decoder.cpp" line="+184"/>
        <source>unknown sentence</source>
        <translation>неизвестное сообщение</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>checksum mismatch: sent %1, computed %2</source>
        <translation>контрольная сумма не совпадает: передано %1, вычислено %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>checksum missing</source>
        <translation>нет контрольной суммы</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>malformed</source>
        <translation>искажённое сообщение</translation>
    </message>
    <message>
        <location filename="../protocol/geostar/geostar_nquery.cpp" line="+39"/>
        <source>not 0-3</source>
        <translation>не 0-3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not 0-3/R</source>
        <translation>не 0-3/R</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>NQUERY reply has more than 10 message codes</source>
        <translation>в ответе NQUERY больше 10 кодов сообщений</translation>
    </message>
    <message>
        <location filename="../protocol/geostar/geostar_rlm.cpp" line="+25"/>
        <location line="+17"/>
        <source>not 15 hex digits</source>
        <translation>не 15 шестнадцатеричных цифр</translation>
    </message>
    <message>
        <location line="-13"/>
        <location line="+18"/>
        <source>not one hex digit</source>
        <translation>не одна шестнадцатеричная цифра</translation>
    </message>
    <message>
        <location line="-13"/>
        <location line="+17"/>
        <source>not 4 or 24 hex digits</source>
        <translation>не 4 и не 24 шестнадцатеричные цифры</translation>
    </message>
    <message>
        <location filename="../protocol/geostar/geostar_rquery.cpp" line="+26"/>
        <source>longer than 8 hex digits</source>
        <translation>длиннее 8 шестнадцатеричных цифр</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>RQUERY reply needs three hex words</source>
        <translation>в ответе RQUERY должно быть три шестнадцатеричных слова</translation>
    </message>
    <message>
        <location filename="../protocol/geostar/geostar_sgg.cpp" line="+31"/>
        <source>JAMDET: unexpected field %1</source>
        <translation>JAMDET: лишнее поле %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>unknown GPSGG message or command &apos;%1&apos;</source>
        <translation>неизвестное сообщение или команда GPSGG «%1»</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>GPSGG,%1 takes no parameters</source>
        <translation>GPSGG,%1 не принимает параметров</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_almanac.cpp" line="+49"/>
        <source>expected 12 (or 11) hex fields after the SV id, got %1</source>
        <translation>после номера спутника ожидается 12 (или 11) шестнадцатеричных полей, получено %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../protocol/nemerix/nemerix_ephemeris.cpp" line="-51"/>
        <source>out of range 1..32</source>
        <translation>вне диапазона 1..32</translation>
    </message>
    <message>
        <location filename="../protocol/geostar/geostar_gns.cpp" line="+61"/>
        <location filename="../protocol/nemerix/nemerix_almanac.cpp" line="+1"/>
        <location filename="../protocol/nemerix/nemerix_ephemeris.cpp" line="+19"/>
        <location filename="../protocol/nemerix/nemerix_fix_settings.cpp" line="-21"/>
        <location line="+17"/>
        <location filename="../protocol/nemerix/nemerix_power.cpp" line="+16"/>
        <location filename="../protocol/nvs/nvs_rzb.cpp" line="+30"/>
        <source>missing</source>
        <translation>отсутствует</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_datum.cpp" line="+44"/>
        <location filename="../protocol/nemerix/nemerix_power.cpp" line="+2"/>
        <location filename="../protocol/nemerix/nemerix_serial.cpp" line="+32"/>
        <source>not 0 or 1</source>
        <translation>не 0 и не 1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not 0..218 or 500</source>
        <translation>не 0..218 и не 500</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>out of range -9999..9999</source>
        <translation>вне диапазона -9999..9999</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of range 6000000..12000000</source>
        <translation>вне диапазона 6000000..12000000</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>out of range 6000000..9000000</source>
        <translation>вне диапазона 6000000..9000000</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_ephemeris.cpp" line="-17"/>
        <source>not 1, 2 or 3</source>
        <translation>не 1, 2 или 3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SV id and subframe are required</source>
        <translation>нужны номер спутника и подкадр</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>subframe %1: expected %2 hex fields, got %3</source>
        <translation>подкадр %1: ожидается %2 шестнадцатеричных полей, получено %3</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_fix_settings.cpp" line="+13"/>
        <source>no mask given</source>
        <translation>маска не задана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mask ids and values must come in pairs</source>
        <translation>номера масок и значения должны идти парами</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too many masks</source>
        <translation>слишком много масок</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>unknown mask (0..10)</source>
        <translation>неизвестная маска (0..10)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>expected h:m</source>
        <translation>ожидается ч:м</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_hex.cpp" line="+14"/>
        <source>does not fit the field&apos;s bit width</source>
        <translation>не помещается в разрядность поля</translation>
    </message>
    <message>
        <location line="+85"/>
        <location filename="../protocol/nemerix/nemerix_settings_report.cpp" line="+52"/>
        <location filename="../protocol/nemerix/nemerix_version.cpp" line="+69"/>
        <source>%1: missing</source>
        <translation>%1: отсутствует</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_iono_utc.cpp" line="-59"/>
        <source>expected the SV id and 8 hex coefficients, got %1 fields</source>
        <translation>ожидаются номер спутника и 8 шестнадцатеричных коэффициентов, получено полей: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>expected the SV id and at least 8 hex fields</source>
        <translation>ожидаются номер спутника и не менее 8 шестнадцатеричных полей</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_nav_init.cpp" line="+2"/>
        <source>out of range 12..16</source>
        <translation>вне диапазона 12..16</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>ECEF x, y and z must be given together</source>
        <translation>ECEF x, y и z задаются вместе</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>latitude, longitude and altitude must be given together</source>
        <translation>широта, долгота и высота задаются вместе</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_output.cpp" line="+50"/>
        <location line="+50"/>
        <source>no message id given</source>
        <translation>не задан номер сообщения</translation>
    </message>
    <message>
        <location line="-49"/>
        <source>message ids and values must come in pairs</source>
        <translation>номера сообщений и значения должны идти парами</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too many entries</source>
        <translation>слишком много записей</translation>
    </message>
    <message>
        <location line="-15"/>
        <location line="+71"/>
        <source>unknown message</source>
        <translation>неизвестное сообщение</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>not 0..3</source>
        <translation>не 0..3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not 0..9</source>
        <translation>не 0..9</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>too many message ids</source>
        <translation>слишком много номеров сообщений</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_power.cpp" line="+2"/>
        <source>out of range 5..10</source>
        <translation>вне диапазона 5..10</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_reset.cpp" line="+40"/>
        <source>out of range 0..255</source>
        <translation>вне диапазона 0..255</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>expected 0..255 or FACTORY/COLD/WARM/HOT</source>
        <translation>ожидается 0..255 или FACTORY/COLD/WARM/HOT</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_serial.cpp" line="+2"/>
        <source>not a supported speed</source>
        <translation>неподдерживаемая скорость</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not 0, 1 or 2</source>
        <translation>не 0, 1 или 2</translation>
    </message>
    <message>
        <location filename="../protocol/nemerix/nemerix_settings_report.cpp" line="-146"/>
        <source>not 0..4</source>
        <translation>не 0..4</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>out of range -13..13</source>
        <translation>вне диапазона -13..13</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>out of range -59..59</source>
        <translation>вне диапазона -59..59</translation>
    </message>
    <message>
        <location filename="../protocol/nmea/gsv.cpp" line="-13"/>
        <source>too many satellites in one GSV sentence</source>
        <translation>слишком много спутников в одном сообщении GSV</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>sentence number outside 1..%1</source>
        <translation>номер сообщения вне диапазона 1..%1</translation>
    </message>
    <message>
        <location filename="../protocol/nmea/query.cpp" line="+14"/>
        <location filename="../protocol/nvs/nvs_cfg.cpp" line="+16"/>
        <location filename="../protocol/nvs/nvs_rzb.cpp" line="-4"/>
        <location line="+11"/>
        <source>empty</source>
        <translation>пусто</translation>
    </message>
    <message>
        <location filename="../protocol/nvs/nvs_idl.cpp" line="-79"/>
        <source>not MODE, ADD, REMOVE, CLEAR, SHOW or a list item</source>
        <translation>не MODE, ADD, REMOVE, CLEAR, SHOW и не элемент списка</translation>
    </message>
    <message>
        <location filename="../protocol/nvs/nvs_rst.cpp" line="+15"/>
        <source>not F or W</source>
        <translation>не F и не W</translation>
    </message>
    <message>
        <location filename="../protocol/core/settings_plan.cpp" line="+44"/>
        <source>&apos;%1&apos; names several settings of the %2 dialect: %3</source>
        <translation>«%1» — имя нескольких настроек диалекта %2: %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting &apos;%1&apos; of the %2 dialect: did you mean %3?</source>
        <translation>неизвестная настройка «%1» диалекта %2: может быть, %3?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown setting &apos;%1&apos; of the %2 dialect (gnss-cli schema %2 lists them)</source>
        <translation>неизвестная настройка «%1» диалекта %2 (их список выводит gnss-cli schema %2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is read-only: the receiver reports it but no command sets it</source>
        <translation>%1 только для чтения: приёмник сообщает её, но ни одна команда её не задаёт</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 is given twice</source>
        <translation>%1 указана дважды</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>%1 is write-only: the receiver cannot report it</source>
        <translation>%1 только для записи: приёмник не может её сообщить</translation>
    </message>
    <message>
        <location filename="../protocol/nvs/nvs_tst.cpp" line="-8"/>
        <source>%1: no test results</source>
        <translation>%1: нет результатов тестов</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: a test result without its test name</source>
        <translation>%1: результат теста без названия теста</translation>
    </message>
</context>
<context>
    <name>Reports</name>
    <message>
        <location filename="schema_texts.cpp" line="+422"/>
        <source>Self-test</source>
        <translation>Самотестирование</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tests</source>
        <translation>Тесты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>name</source>
        <translation>Название</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>result</source>
        <translation>Результат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device_id</source>
        <translation>Идентификатор устройства</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>antenna</source>
        <translation>Антенна</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>antenna_status</source>
        <translation>Состояние антенны</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time pulse</source>
        <translation>Импульс времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>type</source>
        <translation>Тип</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mode</source>
        <translation>Режим</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reference</source>
        <translation>Опорная шкала времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>adjust</source>
        <translation>Подстройка шкалы времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>duration</source>
        <translation>Длительность импульса, мкс</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>validity</source>
        <translation>Контроль достоверности</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cable_delay</source>
        <translation>Задержка в антенном кабеле, нс</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Version</source>
        <translation>Версия</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>manufacturer</source>
        <translation>Производитель</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device</source>
        <translation>Устройство</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rtk_fw</source>
        <translation>Прошивка RTK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>csm_hw</source>
        <translation>Аппаратура CSM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>csm_fw</source>
        <translation>Прошивка CSM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output settings (NQUERY)</source>
        <translation>Настройки вывода (NQUERY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port</source>
        <translation>Порт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate_code</source>
        <translation>Темп выдачи (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate_hz</source>
        <translation>Темп выдачи, Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nmea_version</source>
        <translation>Версия NMEA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>messages</source>
        <translation>Сообщения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>field</source>
        <translation>Поле</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>code</source>
        <translation>Код</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output</source>
        <translation>Выдача</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>note</source>
        <translation>Примечание</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status and configuration (RQUERY)</source>
        <translation>Состояние и конфигурация (RQUERY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>receiver_name</source>
        <translation>Наименование приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware</source>
        <translation>Прошивка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware_version</source>
        <translation>Версия прошивки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware_date</source>
        <translation>Дата прошивки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>status</source>
        <translation>Слово состояния</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw</source>
        <translation>Исходное значение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jamming_detected</source>
        <translation>Обнаружены помехи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flash_write_in_progress</source>
        <translation>Идёт запись во флэш-память</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>geopath_active</source>
        <translation>Режим GeoPath активен</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reference_within_threshold</source>
        <translation>Расхождение с референсными координатами в пределах порога</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>averaging_in_progress</source>
        <translation>Идёт усреднение координат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rtcm_corrections_used</source>
        <translation>Используются поправки RTCM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sbas_corrections_used</source>
        <translation>Используются поправки SBAS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>state</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solution_type</source>
        <translation>Тип решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>extrapolated</source>
        <translation>Координаты экстраполированы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stationary</source>
        <translation>Остановка (статическая навигация)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solution_available</source>
        <translation>Есть решение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>valid_since_start</source>
        <translation>Было достоверное решение после старта</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solution_dim</source>
        <translation>Размерность решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clock_restored_hot_start</source>
        <translation>Шкала времени восстановлена при горячем старте</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gps_iono_utc_available</source>
        <translation>Доступны параметры ионосферы и UTC GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>date_from_nav_message</source>
        <translation>Дата получена из навигационного сообщения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time_from_nav_message</source>
        <translation>Время получено из навигационного сообщения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>almanac_qzss</source>
        <translation>Альманах QZSS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>almanac_galileo</source>
        <translation>Альманах Galileo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>almanac_glonass</source>
        <translation>Альманах GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>almanac_gps</source>
        <translation>Альманах GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>agc_glonass_ok</source>
        <translation>АРУ GLONASS в норме</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>agc_gps_ok</source>
        <translation>АРУ GPS в норме</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settings_loaded_from_flash</source>
        <translation>Настройки загружены из флэш-памяти</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pll_ok</source>
        <translation>PLL в норме</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rtc_ok</source>
        <translation>RTC в норме</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>backup_ram_ok</source>
        <translation>Резервное ОЗУ в норме</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reserved_bits</source>
        <translation>Резервные биты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>config1</source>
        <translation>Регистр конфигурации 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>antenna_power</source>
        <translation>Питание антенны</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>operating_mode</source>
        <translation>Режим работы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raim</source>
        <translation>RAIM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smoothed_pseudoranges</source>
        <translation>Сглаженные псевдодальности</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>power_saving_type</source>
        <translation>Тип энергосбережения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>power_saving_enabled</source>
        <translation>Энергосбережение разрешено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dynamics_code</source>
        <translation>Профиль динамики (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dynamics</source>
        <translation>Профиль динамики</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>kalman_filter</source>
        <translation>Фильтр Калмана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>first_fix_2d_allowed</source>
        <translation>Режим 2D для первого решения разрешён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mode_2d_allowed</source>
        <translation>Режим 2D разрешён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>geopath</source>
        <translation>Режим GeoPath</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pps_time_scale_code</source>
        <translation>Шкала времени 1PPS (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pps_time_scale</source>
        <translation>Шкала времени 1PPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pps_polarity</source>
        <translation>Полярность 1PPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pps_enabled</source>
        <translation>1PPS включён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>search_unused_systems</source>
        <translation>Поиск сигналов неиспользуемых систем</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sbas</source>
        <translation>SBAS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>qzss</source>
        <translation>QZSS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>galileo</source>
        <translation>Galileo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gps</source>
        <translation>GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>glonass</source>
        <translation>GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>config2</source>
        <translation>Регистр конфигурации 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>receiver_type_code</source>
        <translation>Тип приёмника (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>receiver_type</source>
        <translation>Тип приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>datum_code</source>
        <translation>Система координат (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>datum</source>
        <translation>Система координат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>differential_allowed</source>
        <translation>Дифференциальный режим разрешён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sbas_test_mode_allowed</source>
        <translation>Поправки SBAS в тестовом режиме разрешены</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>use_all_satellites</source>
        <translation>Использовать все спутники</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sbas_prn</source>
        <translation>PRN SBAS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settings report (PNMRX603)</source>
        <translation>Отчёт о настройках (PNMRX603)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sequence</source>
        <translation>Порядок выдачи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delay_s</source>
        <translation>Задержка, с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GGA</source>
        <translation>GGA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLL</source>
        <translation>GLL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GSA</source>
        <translation>GSA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GSV</source>
        <translation>GSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMC</source>
        <translation>RMC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VTG</source>
        <translation>VTG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ZDA</source>
        <translation>ZDA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nmrx_enabled</source>
        <translation>Включённые сообщения Nemerix</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uart_settings</source>
        <translation>Настройки UART</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha0</source>
        <translation>alpha0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha0_raw</source>
        <translation>alpha0 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha1</source>
        <translation>alpha1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha1_raw</source>
        <translation>alpha1 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha2</source>
        <translation>alpha2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha2_raw</source>
        <translation>alpha2 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha3</source>
        <translation>alpha3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha3_raw</source>
        <translation>alpha3 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta0</source>
        <translation>beta0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta0_raw</source>
        <translation>beta0 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta1</source>
        <translation>beta1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta1_raw</source>
        <translation>beta1 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta2</source>
        <translation>beta2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta2_raw</source>
        <translation>beta2 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta3</source>
        <translation>beta3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beta3_raw</source>
        <translation>beta3 (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>iono_valid</source>
        <translation>Достоверность ионосферных данных</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>num_blocks</source>
        <translation>Число 20-летних блоков</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tz_hours</source>
        <translation>Часовой пояс, ч</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tz_minutes</source>
        <translation>Часовой пояс, мин</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max_pdop</source>
        <translation>Максимальный PDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max_hdop</source>
        <translation>Максимальный HDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid_sv</source>
        <translation>Маска исключённых спутников</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>excluded_svs</source>
        <translation>Исключённые спутники</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>min_cno</source>
        <translation>Минимальное C/N0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>min_elevation</source>
        <translation>Минимальный угол места</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max_tm</source>
        <translation>Максимальное число каналов</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max_sv_for_fix</source>
        <translation>Максимум спутников в решении</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>acq_threshold_1</source>
        <translation>Порог захвата 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>acq_threshold_2</source>
        <translation>Порог захвата 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>noise_floor</source>
        <translation>Уровень шума</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>kalman_mode</source>
        <translation>Режим фильтра Калмана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>default_altitude</source>
        <translation>Высота по умолчанию</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>correction</source>
        <translation>Поправка геоида EGM96</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dx</source>
        <translation>dx</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dy</source>
        <translation>dy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dz</source>
        <translation>dz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>iflat_raw</source>
        <translation>Обратное сжатие (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>major_axis_raw</source>
        <translation>Большая полуось (код)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inverse_flattening</source>
        <translation>Обратное сжатие</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>semi_major_axis_m</source>
        <translation>Большая полуось, м</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software version (PNMRX600)</source>
        <translation>Версия ПО (PNMRX600)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>version</source>
        <translation>Версия</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fields</source>
        <translation>Поля</translation>
    </message>
</context>
<context>
    <name>Schema/geostar</name>
    <message>
        <location line="-382"/>
        <source>Output messages</source>
        <translation>Выходные сообщения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GGA/GNS output</source>
        <translation>Выдача GGA/GNS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GGA, and GNS in v4.10 (4.10)</source>
        <translation>GGA, а в v4.10 также GNS (4.10)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 4 (GGA rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 4 (код темпа выдачи GGA; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLL output</source>
        <translation>Выдача GLL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Geographic position (4.11)</source>
        <translation>Географические координаты (4.11)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 5 (GLL rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 5 (код темпа выдачи GLL; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GSA output</source>
        <translation>Выдача GSA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DOP and active satellites (4.12)</source>
        <translation>Геометрический фактор ухудшения точности (DOP) и активные спутники (4.12)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 6 (GSA rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 6 (код темпа выдачи GSA; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GSV output</source>
        <translation>Выдача GSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Satellites in view (4.13)</source>
        <translation>Видимые спутники (4.13)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 7 (GSV rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 7 (код темпа выдачи GSV; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMC output</source>
        <translation>Выдача RMC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recommended minimum data (4.14)</source>
        <translation>Минимальный рекомендованный набор данных (4.14)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 8 (RMC rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 8 (код темпа выдачи RMC; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VTG output</source>
        <translation>Выдача VTG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Course and speed (4.15)</source>
        <translation>Скорость и курс относительно земли (4.15)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 9 (VTG rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 9 (код темпа выдачи VTG; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ZDA output</source>
        <translation>Выдача ZDA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time and date (4.16)</source>
        <translation>Время и дата (4.16)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 11 (ZDA rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 11 (код темпа выдачи ZDA; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTM output</source>
        <translation>Выдача DTM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Datum (4.17)</source>
        <translation>Система координат (4.17)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 12 (DTM rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 12 (код темпа выдачи DTM; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RLM output</source>
        <translation>Выдача RLM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Galileo return link message (4.18)</source>
        <translation>Сообщение обратного канала Galileo (RLM) (4.18)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 13 (RLM rate code; 0 = off, 1/2/3/R = on)</source>
        <translation>ответ NQUERY, поле 13 (код темпа выдачи RLM; 0 = выкл., 1/2/3/R = вкл.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA version</source>
        <translation>Версия NMEA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA v2.x</source>
        <translation>NMEA v2.x</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA v4.10</source>
        <translation>NMEA v4.10</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA 0183 standard of the output: v2.x or v4.10 (4.19)</source>
        <translation>Версия стандарта NMEA 0183 для выходных сообщений: v2.x или v4.10 (4.19)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 3 (2 = v2.x, 4 = v4.10)</source>
        <translation>ответ NQUERY, поле 3 (2 = v2.x, 4 = v4.10)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output rate</source>
        <translation>Темп выдачи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hz</source>
        <translation>Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 Hz</source>
        <translation>1 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2 Hz</source>
        <translation>2 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5 Hz</source>
        <translation>5 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>10 Hz</source>
        <translation>10 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Navigation output rate (4.20)</source>
        <translation>Темп выдачи выходных данных (4.20)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NQUERY reply, field 2 (0 = 10 Hz, 1 = 5 Hz, 2 = 2 Hz, 3 = 1 Hz); also RQUERY configuration register 1 bits 19:18</source>
        <translation>ответ NQUERY, поле 2 (0 = 10 Гц, 1 = 5 Гц, 2 = 2 Гц, 3 = 1 Гц); также ответ RQUERY, регистр конфигурации 1, биты 19:18</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power</source>
        <translation>Питание</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power saving</source>
        <translation>Энергосбережение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power saving modes on/off; in FIX-BY-REQUEST sleep, PSM ON wakes the receiver (4.21). Read back inferred from table 8 bit 24 (power saving modes enabled).</source>
        <translation>Включение/выключение режимов энергосбережения; в режиме FIX-BY-REQUEST в состоянии СОН команда PSM ON пробуждает приёмник (4.21). Состояние читается по биту 24 таблицы 8 (режимы энергосбережения разрешены) — это соответствие выведено косвенно.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RQUERY reply, configuration register 1 bit 24</source>
        <translation>ответ RQUERY, регистр конфигурации 1, бит 24</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Navigation</source>
        <translation>Навигация</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Elevation mask</source>
        <translation>Маска угла места</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg</source>
        <translation>град</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Satellites below the mask are not used in the solution (4.22)</source>
        <translation>Спутники с углом места меньше заданной маски не используются в решении (4.22)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not reported by RQUERY or NQUERY</source>
        <translation>не сообщается ни в RQUERY, ни в NQUERY</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Datum</source>
        <translation>Система координат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>WGS-84</source>
        <translation>WGS-84</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PZ-90.11</source>
        <translation>ПЗ-90.11</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user-defined (reported by RQUERY; cannot be selected by an NMEA command)</source>
        <translation>пользовательская (сообщается в RQUERY; NMEA-командой не выбирается)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coordinate system of the navigation output (4.23)</source>
        <translation>Система координат, в которой выдаются навигационные определения (4.23)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RQUERY reply, configuration register 2 bits 15:14 (0 = WGS-84, 1 = PZ-90.11, 2 = user-defined)</source>
        <translation>ответ RQUERY, регистр конфигурации 2, биты 15:14 (0 = WGS-84, 1 = ПЗ-90.11, 2 = пользовательская)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Constellations</source>
        <translation>Системы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GPS only</source>
        <translation>Только GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS only</source>
        <translation>Только GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS+GPS+Galileo</source>
        <translation>GLONASS+GPS+Galileo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS used: GPS only, GLONASS only or GLONASS+GPS+Galileo (4.24)</source>
        <translation>Режим использования ГНСС: только GPS, только GLONASS или совмещённый GLONASS+GPS+Galileo (4.24)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RQUERY reply, configuration register 1 bits 2:0 (Galileo, GPS, GLONASS in use)</source>
        <translation>ответ RQUERY, регистр конфигурации 1, биты 2:0 (использование Galileo, GPS, GLONASS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port</source>
        <translation>Порт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rate</source>
        <translation>Скорость обмена</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bit/s</source>
        <translation>бит/с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port speed; takes effect after the command (4.8)</source>
        <translation>Скорость обмена последовательного порта; вступает в силу после команды (4.8)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not reported (NQUERY gives the port number only)</source>
        <translation>не сообщается (NQUERY выдаёт только номер порта)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop bits</source>
        <translation>Стоповые биты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 stop bit</source>
        <translation>1 стоповый бит</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2 stop bits</source>
        <translation>2 стоповых бита</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port stop bits (4.9)</source>
        <translation>Количество стоповых бит последовательного порта (4.9)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Actions</source>
        <translation>Действия</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restart</source>
        <translation>Перезапуск</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cold start</source>
        <translation>холодный старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warm start</source>
        <translation>тёплый старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hot start</source>
        <translation>горячий старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cold, warm or hot start (4.3-4.5)</source>
        <translation>Холодный, тёплый или горячий старт (4.3-4.5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an action: nothing to read back</source>
        <translation>действие: читать обратно нечего</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save almanacs</source>
        <translation>Сохранить альманахи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>save almanacs to flash</source>
        <translation>сохранить альманахи во Flash</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save almanacs to flash (4.2)</source>
        <translation>Сохранение альманахов во Flash (4.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an action: nothing to read back (RQUERY status bit 30 shows a write in progress)</source>
        <translation>действие: читать обратно нечего (бит 30 слова состояния в ответе RQUERY показывает, что идёт запись)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary protocol</source>
        <translation>Бинарный протокол</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>switch the port to the binary protocol</source>
        <translation>переключить порт в бинарный протокол</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switch the port from NMEA to the binary protocol (4.1)</source>
        <translation>Переключение порта из протокола NMEA в бинарный протокол (4.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to flash</source>
        <translation>Сохранить во флэш</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The almanacs and the settings in force are written to flash.</source>
        <translation>Альманахи и действующие настройки записываются во флэш-память.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cold start</source>
        <translation>Холодный старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts without almanac or ephemeris.</source>
        <translation>Приёмник перезапускается без альманаха и эфемерид.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warm start</source>
        <translation>Тёплый старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts with its almanac.</source>
        <translation>Приёмник перезапускается с альманахом.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hot start</source>
        <translation>Горячий старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts with almanac and ephemeris.</source>
        <translation>Приёмник перезапускается с альманахом и эфемеридами.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GPS+GLONASS, 1 Hz, NMEA 4.10</source>
        <translation>GPS+GLONASS, 1 Гц, NMEA 4.10</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS and GPS (the GeoS-5 combines them with Galileo: mode MIX), 1 Hz, NMEA 4.10, GGA, RMC, GSA and GSV on.</source>
        <translation>GLONASS и GPS (GeoS-5 совмещает их с Galileo: режим MIX), 1 Гц, NMEA 4.10, включены GGA, RMC, GSA и GSV.</translation>
    </message>
</context>
<context>
    <name>Schema/nemerix</name>
    <message>
        <location line="+5"/>
        <source>Serial port</source>
        <translation>Последовательный порт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol</source>
        <translation>Протокол</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA</source>
        <translation>NMEA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nemerix binary (under development)</source>
        <translation>Двоичный Nemerix (в разработке)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port protocol. Sent with the baud rate (serial.baud is required) and parity.</source>
        <translation>Протокол порта. Передаётся вместе со скоростью (требуется serial.baud) и чётностью.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rate</source>
        <translation>Скорость порта</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bit/s</source>
        <translation>бит/с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial speed; the port switches right after the command. The UART word of PNMRX603 message 0 has no documented layout, so the speed cannot be read back.</source>
        <translation>Скорость последовательного порта; порт переключается сразу после команды. Формат слова UART в PNMRX603, сообщение 0, не документирован, поэтому скорость обратно не читается.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parity</source>
        <translation>Чётность</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>None</source>
        <translation>Нет</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odd</source>
        <translation>Нечётная</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Even</source>
        <translation>Чётная</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parity, sent with the baud rate (serial.baud is required).</source>
        <translation>Чётность; передаётся вместе со скоростью (требуется serial.baud).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA output</source>
        <translation>Выдача NMEA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GGA interval</source>
        <translation>Интервал GGA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output interval in seconds (0 = not output). Read back from PNMRX603 message 0, message delays, assumed to be in the order GGA GLL GSA GSV RMC VTG ZDA.</source>
        <translation>Интервал выдачи в секундах (0 = не выдаётся). Читается из PNMRX603, сообщение 0, поля message delay; предполагается порядок GGA GLL GSA GSV RMC VTG ZDA.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 0, message delay (order inferred)</source>
        <translation>PNMRX603, сообщение 0, message delay (порядок предположительный)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLL interval</source>
        <translation>Интервал GLL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GSA interval</source>
        <translation>Интервал GSA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GSV interval</source>
        <translation>Интервал GSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMC interval</source>
        <translation>Интервал RMC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VTG interval</source>
        <translation>Интервал VTG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ZDA interval</source>
        <translation>Интервал ZDA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output sequence</source>
        <translation>Порядок выдачи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Messages to output, in this order, separated by &apos;;&apos; (GGA GLL GSA GSV RMC VTG ZDA); the others are disabled, the listed ones output every second until rate.* changes them. The sequence in PNMRX603 message 0 has no documented layout.</source>
        <translation>Выдаваемые сообщения в нужном порядке через «;» (GGA GLL GSA GSV RMC VTG ZDA); остальные отключаются, перечисленные выдаются раз в секунду, пока настройки rate.* не изменят их интервал. Формат последовательности в PNMRX603, сообщение 0, не документирован.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nemerix messages</source>
        <translation>Сообщения Nemerix</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Almanac (PNMRX300)</source>
        <translation>Альманах (PNMRX300)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disabled</source>
        <translation>Отключено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send now</source>
        <translation>Выдать сейчас</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send on change</source>
        <translation>Выдавать при изменении</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send now and on change</source>
        <translation>Выдать сейчас и при изменении</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the receiver sends its almanac.</source>
        <translation>Когда приёмник выдаёт свой альманах.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ephemeris (PNMRX301)</source>
        <translation>Эфемериды (PNMRX301)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the receiver sends ephemerides.</source>
        <translation>Когда приёмник выдаёт эфемериды.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ionosphere (PNMRX302)</source>
        <translation>Ионосфера (PNMRX302)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the receiver sends ionospheric corrections.</source>
        <translation>Когда приёмник выдаёт ионосферные поправки.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UTC (PNMRX303)</source>
        <translation>UTC (PNMRX303)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the receiver sends GPS-UTC parameters.</source>
        <translation>Когда приёмник выдаёт параметры GPS-UTC.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Health (PNMRX304)</source>
        <translation>Исправность (PNMRX304)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the receiver sends constellation health.</source>
        <translation>Когда приёмник выдаёт данные об исправности спутников группировки.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Datum</source>
        <translation>Датум</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EGM96 correction</source>
        <translation>Поправка EGM96</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No geoid correction</source>
        <translation>Без поправки геоида</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EGM96 geoid correction (datum 216 only)</source>
        <translation>Поправка геоида EGM96 (только датум 216)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply the EGM96 geoid correction (only meaningful with datum 216).</source>
        <translation>Применять поправку геоида EGM96 (имеет смысл только с датумом 216).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, correction mode</source>
        <translation>PNMRX603, сообщение 4, correction mode</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Map datum</source>
        <translation>Датум карты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0-218: internal table; 500: user defined (needs dx, dy, dz, inverse flattening and semi-major axis).</source>
        <translation>0-218: встроенная таблица; 500: пользовательский (нужны dx, dy, dz, обратное сжатие и большая полуось).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, map datum</source>
        <translation>PNMRX603, сообщение 4, map datum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dx</source>
        <translation>Dx</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X offset of the user datum.</source>
        <translation>Сдвиг пользовательского датума по X.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, Dx</source>
        <translation>PNMRX603, сообщение 4, Dx</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dy</source>
        <translation>Dy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y offset of the user datum.</source>
        <translation>Сдвиг пользовательского датума по Y.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, Dy</source>
        <translation>PNMRX603, сообщение 4, Dy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dz</source>
        <translation>Dz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z offset of the user datum.</source>
        <translation>Сдвиг пользовательского датума по Z.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, Dz</source>
        <translation>PNMRX603, сообщение 4, Dz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inverse flattening</source>
        <translation>Обратное сжатие</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1/f of the user ellipsoid (sent as (1/f - 290) x 1e6).</source>
        <translation>1/f пользовательского эллипсоида (передаётся как (1/f - 290) x 1e6).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, inverse flatness</source>
        <translation>PNMRX603, сообщение 4, inverse flatness</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Semi-major axis</source>
        <translation>Большая полуось</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Semi-major axis of the user ellipsoid (sent as (a - 6370000) x 1000).</source>
        <translation>Большая полуось пользовательского эллипсоида (передаётся как (a - 6370000) x 1000).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 4, major axis</source>
        <translation>PNMRX603, сообщение 4, major axis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fix masks</source>
        <translation>Маски решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Local time zone</source>
        <translation>Часовой пояс</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>h:m</source>
        <translation>ч:мин</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Local time zone as hours:minutes, hours -13..13 (mask 0).</source>
        <translation>Местный часовой пояс в виде часы:минуты, часы -13..13 (маска 0).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 1, time offset</source>
        <translation>PNMRX603, сообщение 1, time offset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum PDOP</source>
        <translation>Максимальный PDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 1 (sent x10).</source>
        <translation>Маска 1 (передаётся с множителем x10).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 2, MaxPDOP</source>
        <translation>PNMRX603, сообщение 2, MaxPDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum HDOP</source>
        <translation>Максимальный HDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 2 (sent x10).</source>
        <translation>Маска 2 (передаётся с множителем x10).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 2, MaxHDOP</source>
        <translation>PNMRX603, сообщение 2, MaxHDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum VDOP</source>
        <translation>Максимальный VDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 3 (sent x10). Not in the settings report.</source>
        <translation>Маска 3 (передаётся с множителем x10). В отчёте о настройках отсутствует.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum SNR</source>
        <translation>Минимальное SNR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dB-Hz</source>
        <translation>дБГц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 4.</source>
        <translation>Маска 4.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 2, Min CNO</source>
        <translation>PNMRX603, сообщение 2, Min CNO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum elevation</source>
        <translation>Минимальный угол места</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg</source>
        <translation>град</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 5.</source>
        <translation>Маска 5.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 2, Min Elevation</source>
        <translation>PNMRX603, сообщение 2, Min Elevation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Noise floor</source>
        <translation>Уровень шума</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 6.</source>
        <translation>Маска 6.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 3, Noise floor</source>
        <translation>PNMRX603, сообщение 3, Noise floor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2D mode altitude</source>
        <translation>Высота в режиме 2D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 8: altitude above MSL held in 2D mode. Read back from the report&apos;s &apos;Default altitude&apos; (inferred to be the same value).</source>
        <translation>Маска 8: высота над уровнем моря, которую приёмник удерживает в режиме 2D. Читается из поля «Default altitude» отчёта (предполагается, что это то же значение).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 3, Default altitude</source>
        <translation>PNMRX603, сообщение 3, Default altitude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum altitude</source>
        <translation>Максимальная высота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 10. Not in the settings report.</source>
        <translation>Маска 10. В отчёте о настройках отсутствует.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Navigation mode</source>
        <translation>Режим навигации</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto (hold altitude)</source>
        <translation>Авто (с удержанием высоты)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D (compute altitude)</source>
        <translation>3D (с расчётом высоты)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 7. Not in the settings report (the report&apos;s Kalman mode has no documented meaning).</source>
        <translation>Маска 7. В отчёте о настройках отсутствует (значение поля Kalman mode в отчёте не документировано).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static navigation</source>
        <translation>Статическая навигация</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto</source>
        <translation>Авто</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static</source>
        <translation>Статика</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask 9.</source>
        <translation>Маска 9.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Channel count</source>
        <translation>Число каналов</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum number of tracking modules used.</source>
        <translation>Максимальное число используемых модулей слежения (каналов).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNMRX603 message 2, Max TM</source>
        <translation>PNMRX603, сообщение 2, Max TM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power mode</source>
        <translation>Режим питания</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operating mode</source>
        <translation>Режим работы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fully active</source>
        <translation>Полностью активный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LDCM1 (low duty cycle)</source>
        <translation>LDCM1 (прерывистый режим)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Low power starts only once the receiver has a complete almanac and a fix.</source>
        <translation>Режим пониженного энергопотребления включается, только когда у приёмника есть полный альманах и решение.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RF off period</source>
        <translation>Время отключения РЧ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RF off time between two fixes in LDCM1 (implies power.mode=1).</source>
        <translation>Время отключения РЧ-тракта между двумя решениями в режиме LDCM1 (подразумевает power.mode=1).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore defaults</source>
        <translation>Заводские настройки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver returns to its factory settings and restarts.</source>
        <translation>Приёмник возвращается к заводским настройкам и перезапускается.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cold start</source>
        <translation>Холодный старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts without almanac or ephemeris.</source>
        <translation>Приёмник перезапускается без альманаха и эфемерид.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warm start</source>
        <translation>Тёплый старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts with its almanac.</source>
        <translation>Приёмник перезапускается с альманахом.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hot start</source>
        <translation>Горячий старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts with almanac and ephemeris.</source>
        <translation>Приёмник перезапускается с альманахом и эфемеридами.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimal output for trackers</source>
        <translation>Минимальная выдача для трекеров</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMC once a second and nothing else: the least traffic for a tracker.</source>
        <translation>Только RMC раз в секунду: минимальный трафик для трекера.</translation>
    </message>
</context>
<context>
    <name>Schema/nvs</name>
    <message>
        <location line="-409"/>
        <source>RTK engine</source>
        <translation>Модуль RTK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operation mode</source>
        <translation>Режим работы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Autonomous</source>
        <translation>Автономный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK rover</source>
        <translation>RTK-ровер</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station with automatic antenna position averaging</source>
        <translation>Базовая станция с автоматическим усреднением координат антенны</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK rover + heading (NV08C-RTK-A only)</source>
        <translation>RTK-ровер + курс (только NV08C-RTK-A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setting of operation mode: 0 Autonomous, 1 Base Station, 2 RTK-Rover (by default), 3 Base Station with automatic antenna position averaging, 4 RTK Rover + Heading (NV08C-RTK-A only).</source>
        <translation>Выбор режима работы: 0 — автономный, 1 — базовая станция, 2 — RTK-ровер (по умолчанию), 3 — базовая станция с автоматическим усреднением координат антенны, 4 — RTK-ровер + курс (только NV08C-RTK-A).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PVT rate</source>
        <translation>Темп PVT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hz</source>
        <translation>Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 Hz</source>
        <translation>1 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2 Hz</source>
        <translation>2 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5 Hz</source>
        <translation>5 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>10 Hz</source>
        <translation>10 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PVT rate, Hz (1, 2, 5 by default, 10).</source>
        <translation>Темп решения PVT, Гц (1, 2, 5 по умолчанию, 10).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use GPS</source>
        <translation>Использовать GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>Выкл.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On</source>
        <translation>Вкл.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 - GPS ON (by default), 0 - GPS OFF.</source>
        <translation>1 — GPS включён (по умолчанию), 0 — GPS выключен.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use GLONASS</source>
        <translation>Использовать GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 - GLONASS ON (by default), 0 - GLONASS OFF.</source>
        <translation>1 — GLONASS включён (по умолчанию), 0 — GLONASS выключен.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use SBAS</source>
        <translation>Использовать SBAS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 - SBAS ON (by default), 0 - SBAS OFF.</source>
        <translation>1 — SBAS включена (по умолчанию), 0 — SBAS выключена.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GPS elevation mask (RTK)</source>
        <translation>Маска угла места GPS (RTK)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg</source>
        <translation>град</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GPS Elevation Mask for RTK mode, degrees (5 by default).</source>
        <translation>Маска угла места для GPS в режиме RTK, град (5 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS elevation mask (RTK)</source>
        <translation>Маска угла места GLONASS (RTK)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Elevation Mask for RTK mode, degrees (5 by default).</source>
        <translation>Маска угла места для GLONASS в режиме RTK, град (5 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SBAS elevation mask (RTK)</source>
        <translation>Маска угла места SBAS (RTK)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SBAS Elevation Mask for RTK mode, degrees (5 by default).</source>
        <translation>Маска угла места для SBAS в режиме RTK, град (5 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Elevation mask (autonomous)</source>
        <translation>Маска угла места (автономный режим)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Elevation Mask for Autonomous mode, degrees (5 by default).</source>
        <translation>Маска угла места для автономного режима, град (5 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SNR mask (RTK)</source>
        <translation>Маска SNR (RTK)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dB-Hz</source>
        <translation>дБГц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SNR Mask for RTK mode, dB-Hz (33 by default). Range 0-99 as GSV reports SNR.</source>
        <translation>Маска SNR для режима RTK, дБГц (33 по умолчанию). Диапазон 0-99 — как SNR в сообщении GSV.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SNR mask (autonomous)</source>
        <translation>Маска SNR (автономный режим)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SNR Mask for Autonomous mode, dB-Hz (12 by default). Range 0-99 as GSV reports SNR.</source>
        <translation>Маска SNR для автономного режима, дБГц (12 по умолчанию). Диапазон 0-99 — как SNR в сообщении GSV.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential age threshold</source>
        <translation>Порог возраста поправок</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential age threshold (max age of RTCM data to use for RTK), seconds (45 by default). Range as PNVGBSS reports the data age (up to 999 s).</source>
        <translation>Порог возраста дифференциальных поправок (максимальный возраст данных RTCM, используемых для RTK), с (45 по умолчанию). Диапазон соответствует тому, как PNVGBSS сообщает возраст данных (до 999 с).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station ID</source>
        <translation>Номер базовой станции</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station ID for Base mode, 0 - 4095 (2 by default).</source>
        <translation>Номер станции для режима базовой станции, 0 - 4095 (2 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTCM raw data rate</source>
        <translation>Темп сырых данных RTCM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Same as PVT rate</source>
        <translation>Как темп PVT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every 1 s</source>
        <translation>Раз в 1 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every 2 s</source>
        <translation>Раз в 2 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every 5 s</source>
        <translation>Раз в 5 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every 10 s</source>
        <translation>Раз в 10 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate of RTCM messages with raw data (#1002 and #1010): 0 - same as PVT rate; 1 (by default), 2, 5, 10 - interval between RTCM messages, seconds.</source>
        <translation>Темп выдачи сообщений RTCM с сырыми данными (#1002 и #1010): 0 — как темп PVT; 1 (по умолчанию), 2, 5, 10 — интервал между сообщениями RTCM, с.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base antenna position (ECEF)</source>
        <translation>Координаты антенны базы (ECEF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base Station Antenna Reference Point ECEF-X,Y,Z, m (three values x,y,z).</source>
        <translation>Опорная точка антенны базовой станции ECEF-X,Y,Z, м (три значения x,y,z).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base antenna position (B,L,H)</source>
        <translation>Координаты антенны базы (B,L,H)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rad,rad,m</source>
        <translation>рад,рад,м</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base Station Antenna Reference Point. Two formats: B,L,H (radians for B and L, metres for H) or NMEA format (ddmm.mmmm,N,dddmm.mmmm,E,H).</source>
        <translation>Опорная точка антенны базовой станции. Два формата: B,L,H (радианы для B и L, метры для H) или формат NMEA (ddmm.mmmm,N,dddmm.mmmm,E,H).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base coordinates check threshold</source>
        <translation>Порог проверки координат базы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>BASE coordinates checking threshold, m (500 m by default). If the distance between BASE coordinates and the current 3D position in BASE mode exceeds it, RTCM output stops, the current position is given in NMEA and PNVGBSS shows the distance.</source>
        <translation>Порог проверки координат базы (BASE), м (500 м по умолчанию). Если в режиме BASE расстояние между координатами базы и текущим 3D-положением превышает этот порог, выдача RTCM прекращается, в NMEA выдаётся текущее положение, а PNVGBSS показывает это расстояние.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA coordinates in base mode</source>
        <translation>Координаты NMEA в режиме базы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base coordinates</source>
        <translation>Координаты базы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current 3D coordinates</source>
        <translation>Текущие 3D-координаты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type of coordinates used for NMEA output in BASE mode: 0 - BASE coordinates (by default), 1 - current 3D coordinates.</source>
        <translation>Тип координат, выдаваемых в NMEA в режиме BASE: 0 — координаты базы (по умолчанию), 1 — текущие 3D-координаты.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position averaging time</source>
        <translation>Время усреднения координат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>min</source>
        <translation>мин</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Antenna position averaging time for Base mode, minutes (30 by default).</source>
        <translation>Время усреднения координат антенны в режиме базовой станции, мин (30 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position averaging input</source>
        <translation>Координаты для усреднения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Any valid coordinates</source>
        <translation>Любые достоверные координаты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed &amp; Float</source>
        <translation>Fixed и Float</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed only</source>
        <translation>Только Fixed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type of coordinates used for antenna position averaging: 0 (by default) - any valid coordinates, 1 - Fixed &amp; Float, 2 - Fixed only.</source>
        <translation>Тип координат, используемых для усреднения координат антенны: 0 (по умолчанию) — любые достоверные координаты, 1 — Fixed и Float, 2 — только Fixed.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RAIM</source>
        <translation>RAIM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RAIM mode: 0 - OFF, 1 - ON (by default).</source>
        <translation>Режим RAIM: 0 — выкл., 1 — вкл. (по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Secondary filter mode</source>
        <translation>Режим вторичного фильтра</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disable</source>
        <translation>Отключён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retain</source>
        <translation>Удержание</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transition</source>
        <translation>Переход</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hybrid</source>
        <translation>Гибридный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Secondary filter mode: 0 (by default) DISABLE - output follows the position type with possible jumps; 1 RETAIN - keep the relative offset; 2 TRANSITION - move slowly to the new position type at the Transfer Speed; 3 HYBRID - TRANSITION towards more accurate types, RETAIN towards less accurate ones.</source>
        <translation>Режим вторичного фильтра: 0 (по умолчанию) DISABLE — выходные координаты следуют типу решения, возможны скачки; 1 RETAIN — сохраняется относительное смещение; 2 TRANSITION — плавный переход к новому типу решения со скоростью перехода (Transfer Speed); 3 HYBRID — TRANSITION при переходе к более точным типам решения, RETAIN — к менее точным.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Secondary filter transfer speed</source>
        <translation>Скорость перехода вторичного фильтра</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m/s</source>
        <translation>м/с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transfer Speed for Secondary Filter, m/s (0.05 by default).</source>
        <translation>Скорость перехода (Transfer Speed) вторичного фильтра, м/с (0.05 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delta-phase filter</source>
        <translation>Фильтр дельта-фазы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delta-Phase Filter mode: 0 - OFF (by default), 1 - ON.</source>
        <translation>Режим фильтра дельта-фазы: 0 — выкл. (по умолчанию), 1 — вкл.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VRS mode</source>
        <translation>Режим VRS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VRS mode: 0 - OFF (by default), 1 - ON.</source>
        <translation>Режим VRS: 0 — выкл. (по умолчанию), 1 — вкл.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS inter-channel bias</source>
        <translation>Межканальное смещение GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cycle</source>
        <translation>цикл</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Inter-Channel Bias (0 by default): shift between phases of nearest GLONASS carriers in parts of phase cycle (hence -1..1).</source>
        <translation>Межканальное смещение GLONASS (0 по умолчанию): сдвиг между фазами соседних несущих GLONASS в долях цикла фазы (отсюда диапазон -1..1).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS ICB calibration</source>
        <translation>Калибровка ICB GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Initial calibration (GPS as reference)</source>
        <translation>Начальная калибровка (опора — GPS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Real-time recalibration</source>
        <translation>Перекалибровка в реальном времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Inter-Channel Bias calibration mode: 0 - OFF (default for RTK FW 0028 and earlier), 1 - initial calibration (once, GPS as reference), 2 - real-time recalibration (default for RTK FW 0029).</source>
        <translation>Режим калибровки межканального смещения GLONASS: 0 — выкл. (по умолчанию для прошивки RTK FW 0028 и более ранних), 1 — начальная калибровка (однократно, GPS в качестве опоры), 2 — перекалибровка в реальном времени (по умолчанию для прошивки RTK FW 0029).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS ICB calibration interval</source>
        <translation>Интервал калибровки ICB GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Inter-Channel Bias calibration interval (length of one step of calibration), seconds (20 by default).</source>
        <translation>Интервал калибровки межканального смещения GLONASS (длительность одного шага калибровки), с (20 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS ICB (moving base)</source>
        <translation>ICB GLONASS (подвижная база)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Inter-Channel Bias for moving-base mode (0 by default), in parts of phase cycle (hence -1..1).</source>
        <translation>Межканальное смещение GLONASS для режима подвижной базы (0 по умолчанию), в долях цикла фазы (отсюда диапазон -1..1).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS ICB calibration (moving base)</source>
        <translation>Калибровка ICB GLONASS (подвижная база)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Inter-Channel Bias calibration mode for moving-base mode: 0 - OFF (by default), 1 - initial calibration, 2 - real-time recalibration.</source>
        <translation>Режим калибровки межканального смещения GLONASS для режима подвижной базы: 0 — выкл. (по умолчанию), 1 — начальная калибровка, 2 — перекалибровка в реальном времени.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS ICB calibration interval (moving base)</source>
        <translation>Интервал калибровки ICB GLONASS (подвижная база)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS Inter-Channel Bias calibration interval for moving-base mode, seconds (20 by default).</source>
        <translation>Интервал калибровки межканального смещения GLONASS для режима подвижной базы, с (20 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ANT1-ANT2 base-line length</source>
        <translation>Длина базовой линии ANT1-ANT2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ANT1-ANT2 base-line length for Heading mode, metres (0.0 by default: base-line constraint disabled).</source>
        <translation>Длина базовой линии ANT1-ANT2 для режима определения курса, м (0.0 по умолчанию: ограничение по длине базовой линии отключено).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Initial GPS week</source>
        <translation>Начальная неделя GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Initial GPS Week Number for counting time in Cold Start mode (default value depends on RTK FW release date).</source>
        <translation>Начальный номер недели GPS для отсчёта времени при холодном старте (значение по умолчанию зависит от даты выпуска прошивки RTK FW).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA output</source>
        <translation>Вывод NMEA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time decimals</source>
        <translation>Знаков дробной части времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Number of digits in fractional part of time output, 0 to 6 (2 by default). PNVGNME sets time and position decimals together.</source>
        <translation>Число знаков в дробной части выводимого времени, от 0 до 6 (2 по умолчанию). PNVGNME задаёт число знаков времени и координат одновременно.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none documented (PNVGNME answers only when set)</source>
        <translation>не описано (PNVGNME отвечает только при установке)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position decimals</source>
        <translation>Знаков дробной части координат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Number of digits in fractional part of position output, 0 to 9 (7 by default).</source>
        <translation>Число знаков в дробной части выводимых координат, от 0 до 9 (7 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Talker ID compatibility</source>
        <translation>Совместимость Talker ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GGA and RMC talker always GP</source>
        <translation>Talker ID для GGA и RMC всегда GP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compatibility off: talker as specified</source>
        <translation>Без совместимости: Talker ID по описанию</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 - Talker ID for GGA and RMC always GP (by default); 1 - compatibility mode off, talker ID as specified (GN for combined solutions). Optional field.</source>
        <translation>0 — Talker ID для GGA и RMC всегда GP (по умолчанию); 1 — режим совместимости выключен, Talker ID согласно описанию сообщений (GN для совмещённого решения). Необязательное поле.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ports</source>
        <translation>Порты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM1 baud rate</source>
        <translation>Скорость COM1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bit/s</source>
        <translation>бит/с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port baud rate, in bauds from 4,800 to 460,800 (115,200 by default, Table 1). The receiver answers with PNVGRZA and then switches.</source>
        <translation>Скорость порта в бодах, от 4800 до 460800 (115200 по умолчанию, Table 1). Приёмник отвечает сообщением PNVGRZA и затем переключается на новую скорость.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none documented (PNVGRZA answers only when set)</source>
        <translation>не описано (PNVGRZA отвечает только при установке)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM1 protocol</source>
        <translation>Протокол COM1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disabled</source>
        <translation>Отключён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA 0183</source>
        <translation>NMEA 0183</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTCM</source>
        <translation>RTCM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol type: 0 disable, 1 NMEA 0183, 7 RTCM. Sent together with the baud rate.</source>
        <translation>Тип протокола: 0 — отключён, 1 — NMEA 0183, 7 — RTCM. Передаётся вместе со скоростью порта.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 baud rate</source>
        <translation>Скорость COM2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 protocol</source>
        <translation>Протокол COM2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>USB baud rate</source>
        <translation>Скорость USB</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>USB protocol</source>
        <translation>Протокол USB</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output</source>
        <translation>Вывод</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM1 output messages</source>
        <translation>Сообщения на COM1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Messages transmitted on COM1 and their output rates in PVT update intervals, as ADDRESS:RATE items separated by &apos;;&apos; (&quot;RMC:1;GSV:5;PNVGTST:10&quot;); at most 20 messages. Written as a clear followed by one add.</source>
        <translation>Сообщения, выдаваемые на COM1, и их темп в интервалах обновления PVT, в виде элементов ADDRESS:RATE через «;» («RMC:1;GSV:5;PNVGTST:10»); не более 20 сообщений. Записывается как очистка списка, за которой следует одно добавление.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none documented</source>
        <translation>не описано</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 output messages</source>
        <translation>Сообщения на COM2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Messages transmitted on COM2 and their output rates in PVT update intervals, as ADDRESS:RATE items separated by &apos;;&apos; (&quot;RMC:1;GSV:5;PNVGTST:10&quot;); at most 20 messages. Written as a clear followed by one add.</source>
        <translation>Сообщения, выдаваемые на COM2, и их темп в интервалах обновления PVT, в виде элементов ADDRESS:RATE через «;» («RMC:1;GSV:5;PNVGTST:10»); не более 20 сообщений. Записывается как очистка списка, за которой следует одно добавление.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>USB output messages</source>
        <translation>Сообщения на USB</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Messages transmitted on USB and their output rates in PVT update intervals, as ADDRESS:RATE items separated by &apos;;&apos; (&quot;RMC:1;GSV:5;PNVGTST:10&quot;); at most 20 messages. Written as a clear followed by one add.</source>
        <translation>Сообщения, выдаваемые на USB, и их темп в интервалах обновления PVT, в виде элементов ADDRESS:RATE через «;» («RMC:1;GSV:5;PNVGTST:10»); не более 20 сообщений. Записывается как очистка списка, за которой следует одно добавление.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time pulse</source>
        <translation>Импульс времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time pulse type</source>
        <translation>Тип импульса времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software-synchronised</source>
        <translation>Программно синхронизированный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hardware-synchronised (aligned to internal timescale)</source>
        <translation>Аппаратно синхронизированный (привязан к внутренней шкале времени)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P (by default) - software-synchronised time pulse; A - hardware-synchronised (aligned to internal timescale).</source>
        <translation>P (по умолчанию) — программно синхронизированный импульс времени; A — аппаратно синхронизированный (привязан к внутренней шкале времени).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software time pulse</source>
        <translation>Программный импульс времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interval: pulse at PVT update rate</source>
        <translation>Интервальный: импульс с темпом обновления PVT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1PPS</source>
        <translation>1PPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>I - interval time pulse at PVT update rate; S (by default) - 1PPS, one pulse per second.</source>
        <translation>I — интервальный импульс с темпом обновления PVT; S (по умолчанию) — 1PPS, один импульс в секунду.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1PPS reference</source>
        <translation>Опорная шкала 1PPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UTC(SU)</source>
        <translation>UTC(SU)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GLONASS time</source>
        <translation>Время GLONASS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GPS time</source>
        <translation>Время GPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1PPS time pulse reference: U - UTC (by default), S - UTC(SU), G - GLONASS time, N - GPS time. Applies to 1PPS only.</source>
        <translation>Опорная шкала времени для импульса 1PPS: U — UTC (по умолчанию), S — UTC(SU), G — время GLONASS, N — время GPS. Применяется только к 1PPS.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timescale adjustment</source>
        <translation>Подстройка шкалы времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Internal receiver timescale adjustment: 1 - On (by default), adjusted once the offset to UTC exceeds 1 ms; 0 - Off (not recommended).</source>
        <translation>Подстройка внутренней шкалы времени приёмника: 1 — вкл. (по умолчанию), шкала подстраивается, как только её расхождение с UTC превышает 1 мс; 0 — выкл. (не рекомендуется).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pulse duration</source>
        <translation>Длительность импульса</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>us</source>
        <translation>мкс</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software-defined time pulse duration in microseconds, 1 to 1000 (1000 by default).</source>
        <translation>Длительность программно формируемого импульса времени в микросекундах, от 1 до 1000 (1000 по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PPS validity control</source>
        <translation>Контроль достоверности PPS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enabled</source>
        <translation>Включён</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output PPS only with a valid navigation solution and UTC parameters: E - enabled, D - disabled (by default).</source>
        <translation>Выдавать PPS только при достоверном навигационном решении и наличии параметров UTC: E — включено, D — выключено (по умолчанию).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Antenna cable delay</source>
        <translation>Задержка в антенном кабеле</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ns</source>
        <translation>нс</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delay in antenna cable in nanoseconds (0 by default). Range from the field&apos;s four digits (xxxx).</source>
        <translation>Задержка в антенном кабеле в наносекундах (0 по умолчанию). Диапазон определяется четырьмя цифрами поля (xxxx).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base stations</source>
        <translation>Базовые станции</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station filter</source>
        <translation>Фильтр базовых станций</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Any base station</source>
        <translation>Любая базовая станция</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only base stations from the list</source>
        <translation>Только базовые станции из списка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 - the receiver may use any base station (by default); 1 - only base stations from the list are allowed.</source>
        <translation>0 — приёмник может использовать любую базовую станцию (по умолчанию); 1 — разрешены только базовые станции из списка.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none documented ($PNVGIDL,MODE,&lt;x&gt; is echoed when set)</source>
        <translation>не описано (при установке приёмник возвращает $PNVGIDL,MODE,&lt;x&gt;)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Known base stations</source>
        <translation>Известные базовые станции</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Known base stations (at most 32) as ID:ICB items separated by &apos;;&apos; (&quot;3:0.072;43:0&quot;); ID 0-4095, ICB = GLONASS inter-channel bias in parts of phase cycle. Written as CLEAR then one ADD per station.</source>
        <translation>Известные базовые станции (не более 32) в виде элементов ID:ICB через «;» («3:0.072;43:0»); ID 0-4095, ICB — межканальное смещение GLONASS в долях цикла фазы. Записывается командой CLEAR, а затем по одной команде ADD на каждую станцию.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to flash</source>
        <translation>Сохранить во флэш</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The settings in force are written to flash and survive a power cycle.</source>
        <translation>Действующие настройки записываются во флэш-память и сохраняются после выключения питания.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore defaults</source>
        <translation>Заводские настройки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The saved settings are erased and the receiver restarts with the factory defaults.</source>
        <translation>Сохранённые настройки стираются, и приёмник перезапускается с заводскими настройками.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cold start</source>
        <translation>Холодный старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts without almanac or ephemeris; settings are kept.</source>
        <translation>Приёмник перезапускается без альманаха и эфемерид; настройки сохраняются.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warm start</source>
        <translation>Тёплый старт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The receiver restarts with its almanac; settings are kept.</source>
        <translation>Приёмник перезапускается с имеющимся альманахом; настройки сохраняются.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK rover 5 Hz</source>
        <translation>RTK-ровер 5 Гц</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK rover at 5 Hz on GPS, GLONASS and SBAS; real-time GLONASS bias calibration, hybrid secondary filter.</source>
        <translation>RTK-ровер с темпом 5 Гц по GPS, GLONASS и SBAS; калибровка межканального смещения GLONASS в реальном времени, гибридный вторичный фильтр.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station, averaging 30 min</source>
        <translation>Базовая станция, усреднение 30 мин</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station that averages its antenna position for 30 minutes from any valid fix, then sends RTCM raw data every second.</source>
        <translation>Базовая станция, которая усредняет координаты антенны в течение 30 минут по любому достоверному решению, а затем выдаёт сырые данные RTCM каждую секунду.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moving base with heading</source>
        <translation>Подвижная база с курсом</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK rover with heading (NV08C-RTK-A) at 5 Hz, GLONASS bias calibration for a moving base.</source>
        <translation>RTK-ровер с определением курса (NV08C-RTK-A) с темпом 5 Гц, калибровка межканального смещения GLONASS для подвижной базы.</translation>
    </message>
</context>
<context>
    <name>SiteStore</name>
    <message>
        <location filename="../protocol/sites/site_store.cpp" line="+56"/>
        <location line="+130"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>cannot make the folder %1</source>
        <translation>не удалось создать папку %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+20"/>
        <source>%1: a site file is .json or .csv</source>
        <translation>%1: файл пунктов бывает .json или .csv</translation>
    </message>
    <message>
        <location line="-15"/>
        <location line="+5"/>
        <source>cannot read %1: %2</source>
        <translation>не удалось прочитать %1: %2</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+13"/>
        <source>cannot write %1: %2</source>
        <translation>не удалось записать %1: %2</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>cannot write %1: %2 of %3 bytes written (is the disk full?)</source>
        <translation>не удалось записать %1: записано %2 из %3 байт (диск заполнен?)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>not JSON: %1 at byte %2</source>
        <translation>не JSON: %1 в байте %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a site list (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>не список пунктов (нет &quot;format&quot;: &quot;%1&quot;)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>version %1 of the site list is newer than this program reads (%2)</source>
        <translation>версия %1 списка пунктов новее, чем читает эта программа (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;version&quot; must be %1</source>
        <translation>&quot;version&quot; должно быть %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&quot;sites&quot; must be an array</source>
        <translation>&quot;sites&quot; должно быть массивом</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>site %1</source>
        <translation>пункт %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>site %1 (&quot;%2&quot;)</source>
        <translation>пункт %1 (&quot;%2&quot;)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: not an object</source>
        <translation>%1: не объект</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>field &quot;%1&quot; is missing</source>
        <translation>нет поля &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>field &quot;%1&quot;: not a number</source>
        <translation>поле &quot;%1&quot;: не число</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>field &quot;%1&quot;: not text</source>
        <translation>поле &quot;%1&quot;: не текст</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>field &quot;name&quot; is missing or not text</source>
        <translation>поле &quot;name&quot; отсутствует или не текст</translation>
    </message>
</context>
<context>
    <name>SourceSpec</name>
    <message>
        <location filename="../protocol/link/source_spec.cpp" line="+50"/>
        <source>%1 at %2 baud</source>
        <translation>%1 на скорости %2 бод</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (baud: auto)</source>
        <translation>%1 (скорость: авто)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP %1</source>
        <translation>TCP %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay %1</source>
        <translation>Воспроизведение %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated %1</source>
        <translation>Имитатор %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+12"/>
        <source>gpsd %1</source>
        <translation>gpsd %1</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>No source</source>
        <translation>Нет источника</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>simulated</source>
        <translation>симулятор</translation>
    </message>
</context>
<context>
    <name>StartupOptions</name>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="+21"/>
        <source>Configure and monitor GNSS receivers.</source>
        <translation>Настройка и мониторинг приёмников ГНСС.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Serial port.</source>
        <translation>Последовательный порт.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Baud rate (default: auto).</source>
        <translation>Скорость порта (по умолчанию: автоопределение).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP source HOST:PORT.</source>
        <translation>Источник TCP ХОСТ:ПОРТ.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Replay a recorded log.</source>
        <translation>Воспроизвести записанный журнал.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a log in the offline viewer (a timeline, every dock at its cursor); the same as giving FILE alone.</source>
        <translation>Открыть журнал в просмотрщике (шкала времени, все панели показывают момент под курсором); то же, что указать FILE без ключа.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>With a log: start the viewer at this time of day (10:42:00), UTC time (2024-03-15T10:42:00Z) or epoch (#1200).</source>
        <translation>С журналом: открыть просмотр на этом времени суток (10:42:00), времени UTC (2024-03-15T10:42:00Z) или эпохе (#1200).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A log to open in the viewer.</source>
        <translation>Журнал, который открыть в просмотрщике.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Built-in simulated receiver: %1.</source>
        <translation>Встроенный имитатор приёмника: %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A receiver that gpsd holds: gpsd://HOST[:PORT][/DEVICE] (port 2947 and every device when left out).</source>
        <translation>Приёмник, подключённый к gpsd: gpsd://ХОСТ[:ПОРТ][/УСТРОЙСТВО] (если не указаны — порт 2947 и все устройства).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Show this dock in front of its tab group: settings, console, sky, signal, fix, satellites, rtk, charts, corrections, deviation, attitude, stats, info, history, compare, qualify, base, serve; with a log open also logTrack, logSummary, logCharts, logEvents.</source>
        <translation>Показать эту панель поверх её группы вкладок: settings, console, sky, signal, fix, satellites, rtk, charts, corrections, deviation, attitude, stats, info, history, compare, qualify, base, serve; при открытом журнале также logTrack, logSummary, logCharts, logEvents.</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>--at needs a log to open</source>
        <translation>--at указывается вместе с журналом</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid --at: %1 (write 10:42:00, 2024-03-15T10:42:00Z or #1200)</source>
        <translation>Неверное значение --at: %1 (напишите 10:42:00, 2024-03-15T10:42:00Z или #1200)</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>Give live sources (--port, --tcp, --gpsd, --replay, --sim) or a log to open, not both.</source>
        <translation>Укажите либо источники данных (--port, --tcp, --gpsd, --replay, --sim), либо журнал для просмотра, но не то и другое.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No such log: %1</source>
        <translation>Нет такого журнала: %1</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>Invalid --gpsd: %1</source>
        <translation>Неверное значение --gpsd: %1</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Save an image of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>Exit status: 0 closed normally, 1 the log to open is not there or the --screenshot could not be saved, 2 usage error.</source>
        <translation>Код выхода: 0 окно закрыто, 1 открываемого журнала нет или --screenshot не удалось сохранить, 2 ошибка в командной строке.</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>Quit after this many seconds.</source>
        <translation>Выйти через указанное число секунд.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Unexpected argument &apos;%1&apos;</source>
        <translation>Лишний аргумент «%1»</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Invalid baud rate: %1</source>
        <translation>Неверная скорость порта: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Invalid --quit-after: %1</source>
        <translation>Неверное значение --quit-after: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Unknown simulated receiver &apos;%1&apos; (use %2)</source>
        <translation>Неизвестный имитатор приёмника «%1» (допустимо: %2)</translation>
    </message>
    <message>
        <location filename="../app/gui/window_start.cpp" line="+12"/>
        <source>Unknown dock &apos;%1&apos; (use %2)</source>
        <translation>Неизвестная панель «%1» (допустимо: %2)</translation>
    </message>
</context>
<context>
    <name>Units</name>
    <message>
        <location filename="../ui/models/value_format.cpp" line="+4"/>
        <source>ft</source>
        <translation>фт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>mph</source>
        <translation>миль/ч</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>kn</source>
        <translation>уз</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>m/s</source>
        <translation>м/с</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>km/h</source>
        <translation>км/ч</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>mi</source>
        <translation>миль</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NM</source>
        <translation>мор. миль</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>km</source>
        <translation>км</translation>
    </message>
</context>
<context>
    <name>gnss::app::ConnectionBar</name>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="+1"/>
        <source>&apos;%1&apos; is not HOST:PORT with a port from 1 to 65535.</source>
        <translation>«%1» — не адрес вида ХОСТ:ПОРТ с портом от 1 до 65535.</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="+1"/>
        <source>Serial port by path</source>
        <translation>Последовательный порт по пути</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="+1"/>
        <source>Device path (/dev/serial/by-id/…, /dev/rfcomm0, /dev/pts/3):</source>
        <translation>Путь к устройству (/dev/serial/by-id/…, /dev/rfcomm0, /dev/pts/3):</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="+1"/>
        <source>Port by path…</source>
        <translation>Порт по пути…</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="+20"/>
        <source>Connection</source>
        <translation>Подключение</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Source </source>
        <translation>Источник </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>  Baud </source>
        <translation>  Скорость </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>auto</source>
        <translation>авто</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+111"/>
        <source>Connect</source>
        <translation>Подключить</translation>
    </message>
    <message>
        <location line="-108"/>
        <source>Add receiver</source>
        <translation>Добавить приёмник</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect the source chosen as another receiver: the one shown keeps running</source>
        <translation>Подключить выбранный источник как ещё один приёмник; показанный продолжает работать</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>TCP source</source>
        <translation>Источник TCP</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Host and port (HOST:PORT):</source>
        <translation>Хост и порт (ХОСТ:ПОРТ):</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>gpsd source</source>
        <translation>Источник gpsd</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gpsd&apos;s host, port and device (HOST[:PORT][/DEVICE]; port 2947 and every device when left out):</source>
        <translation>Хост, порт и устройство gpsd (ХОСТ[:ПОРТ][/УСТРОЙСТВО]; если не указаны — порт 2947 и все устройства):</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open Log</source>
        <translation>Открыть журнал</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMEA logs (*.nmea *.log *.txt);;All files (*)</source>
        <translation>Журналы NMEA (*.nmea *.log *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1
Manufacturer: %2
Serial number: %3</source>
        <translation>%1
Производитель: %2
Серийный номер: %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Simulated %1</source>
        <translation>Имитатор %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>TCP…</source>
        <translation>TCP…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gpsd…</source>
        <translation>gpsd…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open log…</source>
        <translation>Открыть журнал…</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Disconnect</source>
        <translation>Отключить</translation>
    </message>
</context>
<context>
    <name>gnss::app::CorrectionsController</name>
    <message>
        <location filename="../app/gui/corrections_controller.cpp" line="+41"/>
        <source>The password was not read from the keychain: %1</source>
        <translation>Пароль не прочитан из связки ключей: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The password was not kept in the keychain: %1</source>
        <translation>Пароль не сохранён в связке ключей: %1</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Showing the RTCM 3 the receiver itself sends</source>
        <translation>Показан RTCM 3, который выдаёт сам приёмник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not started</source>
        <translation>Не запущено</translation>
    </message>
</context>
<context>
    <name>gnss::app::LogPlayer</name>
    <message>
        <location filename="../app/gui/log_player.cpp" line="+44"/>
        <source>no log is open</source>
        <translation>журнал не открыт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed must be above 0 and at most 1000</source>
        <translation>скорость должна быть больше 0 и не больше 1000</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the range is empty</source>
        <translation>интервал пуст</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>choose a serial port and a standard baud rate</source>
        <translation>выберите последовательный порт и стандартную скорость</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>choose a TCP port from 1 to 65535</source>
        <translation>выберите порт TCP от 1 до 65535</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot make a pseudo-terminal: %1</source>
        <translation>не удалось создать псевдотерминал: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>cannot listen on 127.0.0.1:%1: %2</source>
        <translation>не удалось открыть порт 127.0.0.1:%1: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cannot open %1: %2</source>
        <translation>не удалось открыть %1: %2</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>Not playing</source>
        <translation>Не воспроизводится</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pseudo-terminal %1</source>
        <translation>Псевдотерминал %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>127.0.0.1:%1, waiting for a client</source>
        <translation>127.0.0.1:%1, ожидание клиента</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>127.0.0.1:%1, clients: %2</source>
        <translation>127.0.0.1:%1, клиентов: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 at %2 baud</source>
        <translation>%1 на скорости %2 бод</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: epoch %2 of %3, %4 kB sent</source>
        <translation>%1: эпоха %2 из %3, отправлено %4 кБ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: finished, %2 of %3 epochs, %4 kB sent</source>
        <translation>%1: готово, эпох %2 из %3, отправлено %4 кБ</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>, %1 kB dropped (the reader did not keep up)</source>
        <translation>, потеряно %1 кБ (читающая сторона не успевала)</translation>
    </message>
</context>
<context>
    <name>gnss::app::LogViewer</name>
    <message>
        <location filename="../app/gui/log_viewer.cpp" line="+156"/>
        <source>Log %1: unpacking, %2 %</source>
        <translation>Журнал %1: распаковка, %2 %</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Log %1: indexing, %2 % of %3 MB</source>
        <translation>Журнал %1: индексация, %2 % из %3 МБ</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+3"/>
        <source>Log %1: cancelling…</source>
        <translation>Журнал %1: отмена…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Log %1: indexing cancelled at %2 %: the first %3 epochs are shown (open it again to index it all)</source>
        <translation>Журнал %1: индексация отменена на %2 %: показаны первые эпохи (%3) (откройте его снова, чтобы проиндексировать целиком)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Log %1: indexing cancelled (open it again to index it)</source>
        <translation>Журнал %1: индексация отменена (откройте его снова, чтобы проиндексировать)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+6"/>
        <source>Log %1: %2</source>
        <translation>Журнал %1: %2</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Log %1: no epochs found</source>
        <translation>Журнал %1: эпох не найдено</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Log %1: %2 epochs</source>
        <translation>Журнал %1: эпох — %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> · %1</source>
        <translation> · %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> · following</source>
        <translation> · слежение за файлом</translation>
    </message>
    <message>
        <location line="+219"/>
        <source>no log is open, or it is still being indexed</source>
        <translation>журнал не открыт или ещё индексируется</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>an export is already running</source>
        <translation>экспорт уже идёт</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Exported epochs %1 to %2 to %3</source>
        <translation>Эпохи с %1 по %2 экспортированы в %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Could not write %1 (the disk is full, or the folder is not writable)</source>
        <translation>Не удалось записать %1 (диск заполнен или нет прав на запись в папку)</translation>
    </message>
</context>
<context>
    <name>gnss::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window_sessions.cpp" line="+1"/>
        <source>%1 is receiver %2 already (%3): choose another port.</source>
        <translation>%1 уже используется приёмником %2 (%3): выберите другой порт.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+44"/>
        <location filename="../app/gui/main_window_log.cpp" line="+286"/>
        <source>GNSS Workbench</source>
        <translation>GNSS Workbench</translation>
    </message>
    <message>
        <location line="+147"/>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_log.cpp" line="-236"/>
        <source>Timeline</source>
        <translation>Шкала времени</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Log timeline</source>
        <translation>Шкала времени журнала</translation>
    </message>
    <message>
        <location filename="../app/gui/dock_table.cpp" line="+90"/>
        <source>Events</source>
        <translation>События</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Log events</source>
        <translation>События журнала</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_docks.cpp" line="+416"/>
        <source>Save events</source>
        <translation>Сохранить события</translation>
    </message>
    <message>
        <location line="-123"/>
        <location line="+123"/>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <location line="-125"/>
        <source>Export the comparison</source>
        <translation>Экспорт сравнения</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Saved %1</source>
        <translation>Сохранено: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not saved: %1</source>
        <translation>Не сохранено: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Save the qualification report</source>
        <translation>Сохранить отчёт о квалификации</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Report written: %1</source>
        <translation>Отчёт записан: %1</translation>
    </message>
    <message>
        <location line="+80"/>
        <location line="+15"/>
        <location filename="../app/gui/main_window_log.cpp" line="+255"/>
        <source>Not exported: %1</source>
        <translation>Не экспортировано: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dock_table.cpp" line="-7"/>
        <source>Log statistics</source>
        <translation>Статистика журнала</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Log statistics (range)</source>
        <translation>Статистика журнала (интервал)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_docks.cpp" line="-5"/>
        <source>Save statistics</source>
        <translation>Сохранить статистику</translation>
    </message>
    <message>
        <location line="-136"/>
        <location line="+138"/>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/dock_table.cpp" line="+2"/>
        <source>Log charts</source>
        <translation>Графики журнала</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Log charts (whole log)</source>
        <translation>Графики журнала (весь журнал)</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Track</source>
        <translation>Трек</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Signal history</source>
        <translation>Сигналы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Signal history and C/N0 map</source>
        <translation>История сигналов и карта C/N0</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compare</source>
        <translation>Сравнение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compare receivers</source>
        <translation>Сравнение приёмников</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Qualification</source>
        <translation>Квалификация</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Qualification (TTFF, accuracy)</source>
        <translation>Квалификация (TTFF, точность)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Base</source>
        <translation>База</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Serve</source>
        <translation>Раздача</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serve streams (NTRIP caster, TCP)</source>
        <translation>Раздача потоков (NTRIP-кастер, TCP)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Track (whole log)</source>
        <translation>Трек (весь журнал)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_log.cpp" line="-164"/>
        <source>&amp;Open Log...</source>
        <translation>&amp;Открыть журнал...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>NMEA logs (*.nmea *.log *.txt *.gz *.nmea.gz);;All files (*)</source>
        <translation>Журналы NMEA (*.nmea *.log *.txt *.gz *.nmea.gz);;Все файлы (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open &amp;Recent</source>
        <translation>Открыть &amp;недавний</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Export Log...</source>
        <translation>&amp;Экспорт журнала...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Play Out...</source>
        <translation>&amp;Воспроизвести наружу...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Close Log</source>
        <translation>&amp;Закрыть журнал</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--at: %1</source>
        <translation>--at: %1</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Clear the list</source>
        <translation>Очистить список</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1 — GNSS Workbench</source>
        <translation>%1 — GNSS Workbench</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Export epochs %1 to %2</source>
        <translation>Экспорт эпох с %1 по %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export the whole log</source>
        <translation>Экспорт всего журнала</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GPX track (*.gpx);;KML, coloured by fix (*.kml);;CSV, one row per epoch (*.csv);;NMEA, the bytes as in the file (*.nmea);;Statistics (*.json)</source>
        <translation>Трек GPX (*.gpx);;KML, цвет по типу решения (*.kml);;CSV, строка на эпоху (*.csv);;NMEA, байты как в файле (*.nmea);;Статистика (*.json)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>name the file .gpx, .kml, .csv, .nmea or .json: the suffix says the format</source>
        <translation>назовите файл .gpx, .kml, .csv, .nmea или .json: формат задаётся расширением</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exporting to %1…</source>
        <translation>Экспорт в %1…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+8"/>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Receiver</source>
        <translation>&amp;Приёмник</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About GNSS Workbench</source>
        <translation>&amp;О программе GNSS Workbench</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Configure and monitor these receivers: %2.</source>
        <translation>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Настройка и наблюдение за приёмниками: %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About &amp;Qt</source>
        <translation>О &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_log.cpp" line="-161"/>
        <source>Open Log</source>
        <translation>Открыть журнал</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="-148"/>
        <source>trying %1…</source>
        <translation>проверка %1…</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../app/gui/main_window_sessions.cpp" line="+135"/>
        <source>→ %1</source>
        <translation>→ %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not found</source>
        <translation>не найдена</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Command: %1</source>
        <translation>Команда: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dock_table.cpp" line="-55"/>
        <location line="+1"/>
        <source>Sky plot</source>
        <translation>Небосвод</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Fix and position</source>
        <translation>Решение и координаты</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Fix</source>
        <translation>Решение</translation>
    </message>
    <message>
        <location line="-6"/>
        <location line="+1"/>
        <source>Signal levels</source>
        <translation>Уровни сигналов</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+1"/>
        <source>Satellites</source>
        <translation>Спутники</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+1"/>
        <source>Console</source>
        <translation>Консоль</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Statistics</source>
        <translation>Статистика</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Message statistics</source>
        <translation>Статистика сообщений</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Receiver information</source>
        <translation>Сведения о приёмнике</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+1"/>
        <source>RTK</source>
        <translation>RTK</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+1"/>
        <source>Charts</source>
        <translation>Графики</translation>
    </message>
    <message>
        <location line="-31"/>
        <location line="+1"/>
        <source>Deviation</source>
        <translation>Разброс</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Attitude</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude and time marks</source>
        <translation>Ориентация и метки времени</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Corrections</source>
        <translation>Поправки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Corrections (RTCM)</source>
        <translation>Поправки (RTCM)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Settings</source>
        <translation>Настройки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Receiver settings</source>
        <translation>Настройки приёмника</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_docks.cpp" line="-279"/>
        <source>Not sent: %1</source>
        <translation>Не отправлено: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+45"/>
        <source>&amp;Record...</source>
        <translation>&amp;Запись...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Edit</source>
        <translation>&amp;Правка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Preferences...</source>
        <translation>&amp;Параметры...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+,</source>
        <translation>Ctrl+,</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Connect</source>
        <translation>&amp;Подключить</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Отключить</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Add Receiver</source>
        <translation>&amp;Добавить приёмник</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ctrl+Shift+N</source>
        <translation>Ctrl+Shift+N</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;name Receiver...</source>
        <translation>Пере&amp;именовать приёмник...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;lose Receiver</source>
        <translation>&amp;Закрыть приёмник</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Another &amp;dock for this receiver</source>
        <translation>Ещё одна &amp;панель для этого приёмника</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Sky plot &amp;tracks</source>
        <translation>&amp;Треки на небосводе</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Reset layout</source>
        <translation>&amp;Сбросить расположение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;heme</source>
        <translation>&amp;Оформление</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Follow the system</source>
        <translation>Как в системе</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Light</source>
        <translation>Светлое</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dark</source>
        <translation>Тёмное</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>About GNSS Workbench</source>
        <translation>О программе GNSS Workbench</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>NMEA-0183 (no vendor sentences)</source>
        <translation>NMEA-0183 (без фирменных сообщений)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dialect: —</source>
        <translation>диалект: —</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (firmware %1)</source>
        <translation> (прошивка %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 B/s · %2 sentences/s</source>
        <translation>%1 Б/с · %2 предл./с</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>checksum errors: %1</source>
        <translation>ошибок контрольной суммы: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>● REC</source>
        <translation>● ЗАПИСЬ</translation>
    </message>
    <message>
        <location line="+10"/>
        <location filename="../app/gui/main_window_sessions.cpp" line="+238"/>
        <source>No fix</source>
        <translation>Нет решения</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Record every receiver to</source>
        <translation>Записывать все приёмники в папку</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Record to</source>
        <translation>Записывать в</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMEA logs (*.nmea)</source>
        <translation>Журналы NMEA (*.nmea)</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+6"/>
        <source>Record</source>
        <translation>Запись</translation>
    </message>
    <message>
        <location line="-228"/>
        <location line="+167"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>Cannot record to %1: connect to a receiver first, and check the folder is writable.</source>
        <translation>Не удаётся записывать в %1: сначала подключитесь к приёмнику и проверьте, что папка доступна для записи.</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>The new language is used from the next start of GNSS Workbench.</source>
        <translation>Новый язык будет использован при следующем запуске GNSS Workbench.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_sessions.cpp" line="-187"/>
        <source>%1 keeps what was begun for %2: pinned to it</source>
        <translation>%1 сохраняет начатое для %2: закреплено за ним</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Follow the selected receiver</source>
        <translation>Показывать выбранный приёмник</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Pin to %1</source>
        <translation>Закрепить за %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Another dock like this one</source>
        <translation>Ещё одна такая панель</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Close this dock</source>
        <translation>Закрыть эту панель</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 · #%2 (pinned)</source>
        <translation>%1 · №%2 (закреплена)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 · #%2</source>
        <translation>%1 · №%2</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Silent for %1 s</source>
        <translation>Молчит %1 с</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 baud</source>
        <translation>%1 бод</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 sentences/s</source>
        <translation>%1 сообщ./с</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n ошибка</numerusform>
            <numerusform>%n ошибки</numerusform>
            <numerusform>%n ошибок</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 KiB skipped</source>
        <translation>пропущено %1 КиБ</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n RTCM frame(s)</source>
        <translation>
            <numerusform>%n кадр RTCM</numerusform>
            <numerusform>%n кадра RTCM</numerusform>
            <numerusform>%n кадров RTCM</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No data</source>
        <translation>Нет данных</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+11"/>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Rename receiver</source>
        <translation>Переименовать приёмник</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Name (empty: its model and port):</source>
        <translation>Имя (пусто: модель и порт):</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Not recording %1: connect it first, and check %2 is writable.</source>
        <translation>Не записывается %1: сначала подключите его и проверьте, что в %2 можно писать.</translation>
    </message>
</context>
<context>
    <name>gnss::app::PasswordKeychain</name>
    <message>
        <location filename="../app/gui/password_keychain.cpp" line="+36"/>
        <location line="+16"/>
        <source>this build has no keychain support</source>
        <translation>эта сборка не поддерживает связку ключей</translation>
    </message>
</context>
<context>
    <name>gnss::app::PlayOutDialog</name>
    <message>
        <location filename="../app/gui/play_out_dialog.cpp" line="+22"/>
        <source>Play Out</source>
        <translation>Воспроизвести наружу</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Send the log to other software at its own pace, as a receiver would: the bytes exactly as in the file.</source>
        <translation>Передать журнал другой программе в его собственном темпе, как это делал бы приёмник: байты в точности как в файле.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Epochs:</source>
        <translation>Эпохи:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A new pseudo-terminal</source>
        <translation>Новый псевдотерминал</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A TCP server on 127.0.0.1</source>
        <translation>Сервер TCP на 127.0.0.1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A serial port</source>
        <translation>Последовательный порт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To:</source>
        <translation>Куда:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>TCP port:</source>
        <translation>Порт TCP:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Serial port:</source>
        <translation>Последовательный порт:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate:</source>
        <translation>Скорость, бод:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>×</source>
        <translation>×</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed:</source>
        <translation>Скорость:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start again at the end</source>
        <translation>По достижении конца начать снова</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+41"/>
        <source>Start</source>
        <translation>Начать</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+27"/>
        <source>Not started: %1</source>
        <translation>Не начато: %1</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Stop</source>
        <translation>Остановить</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 to %2 (the selected range)</source>
        <translation>с %1 по %2 (выбранный интервал)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 to %2 (the whole log)</source>
        <translation>с %1 по %2 (весь журнал)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no log is open</source>
        <translation>журнал не открыт</translation>
    </message>
</context>
<context>
    <name>gnss::app::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/preferences_dialog.cpp" line="+29"/>
        <source>Preferences</source>
        <translation>Параметры</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>System (%1)</source>
        <translation>Как в системе (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Language:</source>
        <translation>&amp;Язык:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used from the next start of GNSS Workbench.</source>
        <translation>Новый язык будет использован при следующем запуске GNSS Workbench.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Follow the system</source>
        <translation>Как в системе</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Light</source>
        <translation>Светлое</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dark</source>
        <translation>Тёмное</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Theme:</source>
        <translation>&amp;Оформление:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Metric (m, m/s, km)</source>
        <translation>Метрические (м, м/с, км)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Imperial (ft, mph, mi)</source>
        <translation>Английские (фт, миль/ч, мили)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nautical (m, kn, NM)</source>
        <translation>Морские (м, уз, мор. мили)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Units:</source>
        <translation>&amp;Единицы:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Coordinates:</source>
        <translation>&amp;Координаты:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Local time (%1)</source>
        <translation>Местное время (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>T&amp;ime:</source>
        <translation>&amp;Время:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The serial speeds baud &quot;auto&quot; tries, in this order, separated by commas</source>
        <translation>Скорости порта, которые перебирает режим «авто», в этом порядке, через запятую</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Baud rates to try:</source>
        <translation>&amp;Скорости для перебора:</translation>
    </message>
</context>
<context>
    <name>gnss::app::QualificationController</name>
    <message>
        <location filename="../app/gui/qualification_controller.cpp" line="+95"/>
        <source>%1: not connected</source>
        <translation>%1: не подключён</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+5"/>
        <location line="+92"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-90"/>
        <source>No receiver to qualify.</source>
        <translation>Нет приёмника для квалификации.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Nothing was sent.</source>
        <translation>Ничего не отправлено.</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>The qualification campaign has ended.</source>
        <translation>Серия испытаний завершена.</translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>%1: done, %n run(s)</source>
        <translation>
            <numerusform>%1: готово, %n запуск</numerusform>
            <numerusform>%1: готово, %n запуска</numerusform>
            <numerusform>%1: готово, %n запусков</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gnss::app::ReceiverChip</name>
    <message>
        <location filename="../app/gui/receivers_strip.cpp" line="+47"/>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
</context>
<context>
    <name>gnss::app::ReceiversStrip</name>
    <message>
        <location line="+35"/>
        <source>Receivers</source>
        <translation>Приёмники</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Show in the docks</source>
        <translation>Показать в панелях</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rename...</source>
        <translation>Переименовать...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disconnect</source>
        <translation>Отключить</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close receiver</source>
        <translation>Закрыть приёмник</translation>
    </message>
</context>
<context>
    <name>gnss::app::ServeController</name>
    <message>
        <location filename="../app/gui/serve_controller.cpp" line="+71"/>
        <source>RTCM of %1</source>
        <translation>RTCM от %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Corrections fed to %1</source>
        <translation>Поправки, подаваемые в %1</translation>
    </message>
    <message>
        <location line="+42"/>
        <location line="+54"/>
        <source>&apos;%1&apos; is not an IP address</source>
        <translation>«%1» — не IP-адрес</translation>
    </message>
    <message>
        <location line="-53"/>
        <source>Tick a stream to serve</source>
        <translation>Отметьте поток для раздачи</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Give both a user and a password, or neither</source>
        <translation>Укажите и пользователя, и пароль, или ни того, ни другого</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Mountpoint &apos;%1&apos;: %2</source>
        <translation>Точка подключения «%1»: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Mountpoint &apos;%1&apos; is given twice</source>
        <translation>Точка подключения «%1» указана дважды</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>NTRIP client %1 refused (%2): %3</source>
        <translation>Клиенту NTRIP %1 отказано (%2): %3</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>No receiver to share</source>
        <translation>Нет приёмника для раздачи</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Client %1 dropped</source>
        <translation>Клиент %1 отключён</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Serving %1 on %2</source>
        <translation>Раздаётся %1 на %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not serving</source>
        <translation>Не раздаётся</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sharing %1 on %2</source>
        <translation>%1 раздаётся на %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not sharing</source>
        <translation>Не раздаётся</translation>
    </message>
    <message>
        <location filename="../app/gui/serve_controller.h" line="+72"/>
        <source>raw</source>
        <translation>TCP</translation>
    </message>
</context>
<context>
    <name>gnss::config::SettingsEngine</name>
    <message>
        <location filename="../protocol/config/settings_engine.cpp" line="+27"/>
        <source>verified</source>
        <translation>проверено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirmed by its reply (write-only)</source>
        <translation>подтверждено ответом (только запись)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused before sending</source>
        <translation>отклонено до отправки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not taken</source>
        <translation>не принято</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not reported</source>
        <translation>не сообщено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sent (write-only, not verifiable)</source>
        <translation>отправлено (только запись, проверить нельзя)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not applied (command failed)</source>
        <translation>не применено (ошибка команды)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>taken, not read back: the link was lost (read back when it returns)</source>
        <translation>принято, обратно не прочитано: связь потеряна (будет прочитано, когда она вернётся)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unconfirmed: the link was lost before the answer (read back when it returns)</source>
        <translation>не подтверждено: связь потеряна до ответа (будет прочитано, когда она вернётся)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>the link changed during the operation</source>
        <translation>подключение сменилось во время операции</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1 cannot take commands</source>
        <translation>%1 не принимает команды</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Read back after the link returned</source>
        <translation>Чтение после восстановления связи</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1 (set here; write-only, not read back)</source>
        <translation>%1 (задано здесь; только запись, обратно не читается)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown (write-only)</source>
        <translation>неизвестно (только запись)</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>no receiver dialect known yet: connect to a receiver first</source>
        <translation>диалект приёмника ещё не известен: сначала подключитесь к приёмнику</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not connected to a receiver</source>
        <translation>нет подключения к приёмнику</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Read settings</source>
        <translation>Чтение настроек</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Apply settings</source>
        <translation>Применение настроек</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 cannot be set</source>
        <translation>%1 нельзя задать</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>nothing was sent: %1</source>
        <translation>ничего не отправлено: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Action</source>
        <translation>Действие</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the %1 receiver has no &apos;%2&apos; command</source>
        <translation>у приёмника %1 нет команды «%2»</translation>
    </message>
    <message>
        <location line="-213"/>
        <location line="+327"/>
        <source>could not read back: %1</source>
        <translation>не удалось прочитать обратно: %1</translation>
    </message>
    <message>
        <location line="+157"/>
        <source>Apply profile</source>
        <translation>Применение профиля</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::CorrectionSource</name>
    <message>
        <location filename="../protocol/corrections/correction_source.cpp" line="+11"/>
        <source>Not started</source>
        <translation>Не запущено</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1; trying again in %2 s</source>
        <translation>%1; повтор через %2 с</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>No data from %1 for %2 s</source>
        <translation>Нет данных от %1 в течение %2 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No answer from %1 within %2 s</source>
        <translation>Нет ответа от %1 за %2 с</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 refused the connection: nothing is listening on that port</source>
        <translation>%1: соединение отклонено — этот порт никто не слушает</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Host %1 not found: check the name and the network</source>
        <translation>Хост %1 не найден: проверьте имя и сеть</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 did not answer in time</source>
        <translation>%1: ответ не получен вовремя</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 closed the connection</source>
        <translation>%1: соединение закрыто другой стороной</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Network error on the way to %1: %2</source>
        <translation>Сетевая ошибка на пути к %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection to %1 failed: %2</source>
        <translation>Не удалось подключиться к %1: %2</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::FileCorrectionSource</name>
    <message>
        <location filename="../protocol/corrections/file_correction_source.cpp" line="+33"/>
        <source>Cannot read %1: %2</source>
        <translation>Не удаётся прочитать %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 holds no RTCM 3 frames</source>
        <translation>В %1 нет кадров RTCM 3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Playing %1 (%2 frames, %3 s at speed %4)</source>
        <translation>Воспроизведение %1 (кадров: %2, %3 с на скорости %4)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Played %1 to the end</source>
        <translation>Файл %1 воспроизведён до конца</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::NtripSource</name>
    <message>
        <location filename="../protocol/corrections/ntrip_source.cpp" line="+87"/>
        <source>No mountpoint given for %1: pick one from its source table</source>
        <translation>Не указана точка подключения для %1: выберите её из таблицы источников</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connecting to %1</source>
        <translation>Подключение к %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Cannot ask %1 for data: %2</source>
        <translation>Не удаётся запросить данные у %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connected to %1, asking for %2 (NTRIP %3)</source>
        <translation>Подключено к %1, запрашивается %2 (NTRIP %3)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>asked NTRIP 2, the caster answered %1</source>
        <translation>запрошен NTRIP 2, кастер ответил по %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, chunked</source>
        <translation>, chunked</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Receiving RTCM from %1 (%2)</source>
        <translation>Приём RTCM от %1 (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Mountpoint %1 is not on %2: the caster sent its source table instead of data (%3 reply)</source>
        <translation>Точки подключения %1 нет на %2: кастер прислал таблицу источников вместо данных (ответ %3)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 refused the user name or password for mountpoint %2 (401 Unauthorized, %3 reply)</source>
        <translation>%1: имя пользователя или пароль для точки подключения %2 не приняты (401 Unauthorized, ответ %3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mountpoint %1 not found on %2 (404 Not Found, %3 reply)</source>
        <translation>Точка подключения %1 не найдена на %2 (404 Not Found, ответ %3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 answered &quot;%2&quot; for mountpoint %3 (%4 reply)</source>
        <translation>%1 ответил «%2» для точки подключения %3 (ответ %4)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 answered &quot;%2&quot; for mountpoint %3 (%4)</source>
        <translation>%1 ответил «%2» для точки подключения %3 (%4)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 answered with %2, not GNSS data: is it an NTRIP caster?</source>
        <translation>%1 ответил типом %2, а не данными ГНСС: это точно NTRIP-кастер?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 did not answer like an NTRIP caster (it sent &quot;%2&quot;); a base&apos;s raw RTCM port needs a TCP source instead</source>
        <translation>%1 ответил не как NTRIP-кастер (прислано «%2»); для порта базы, выдающего RTCM напрямую, выберите источник TCP</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 sent malformed chunked data: %2</source>
        <translation>%1: некорректные данные в кодировке chunked: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 ended the stream (last chunk)</source>
        <translation>%1: поток завершён (последний блок)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 closed the connection without answering</source>
        <translation>%1: соединение закрыто без ответа</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 closed the connection mid-stream after %2 bytes</source>
        <translation>%1: соединение закрыто посреди потока (принято байт: %2)</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::RawCorrectionSource</name>
    <message>
        <location filename="../protocol/corrections/raw_correction_source.cpp" line="+10"/>
        <source>Receiving RTCM from %1</source>
        <translation>Приём RTCM от %1</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::SerialCorrectionSource</name>
    <message>
        <location filename="../protocol/corrections/serial_correction_source.cpp" line="+14"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 at %2 baud</source>
        <translation>%1 на скорости %2 бод</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Opening %1</source>
        <translation>Открытие %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cannot open %1: %2</source>
        <translation>Не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 open, waiting for RTCM</source>
        <translation>%1 открыт, ожидание RTCM</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>No data on %1 for %2 s (is the radio receiving the base?)</source>
        <translation>Нет данных на %1 в течение %2 с (принимает ли радиомодем сигнал базы?)</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::SourceTableRequest</name>
    <message>
        <location filename="../protocol/corrections/source_table_request.cpp" line="+33"/>
        <source>No source table from %1 within %2 s</source>
        <translation>Таблица источников от %1 не получена за %2 с</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot ask %1 for its source table: %2</source>
        <translation>Не удаётся запросить таблицу источников у %1: %2</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>%1 answered with %2, not a source table: is it an NTRIP caster?</source>
        <translation>%1 ответил типом %2, а не таблицей источников: это точно NTRIP-кастер?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 refused the user name or password for its source table (401 Unauthorized, %2 reply)</source>
        <translation>%1: имя пользователя или пароль для таблицы источников не приняты (401 Unauthorized, ответ %2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 sent data instead of its source table (%2 reply)</source>
        <translation>%1 прислал данные вместо таблицы источников (ответ %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 did not answer like an NTRIP caster (it sent &quot;%2&quot;)</source>
        <translation>%1 ответил не как NTRIP-кастер (прислано «%2»)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 answered &quot;%2&quot; instead of its source table (%3 reply)</source>
        <translation>%1 ответил «%2» вместо таблицы источников (ответ %3)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 sent a malformed chunked source table: %2</source>
        <translation>%1: некорректная таблица источников в кодировке chunked: %2</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 closed the connection without answering</source>
        <translation>%1: соединение закрыто без ответа</translation>
    </message>
</context>
<context>
    <name>gnss::corrections::TcpCorrectionSource</name>
    <message>
        <location filename="../protocol/corrections/tcp_correction_source.cpp" line="+11"/>
        <source>Connected to %1, waiting for RTCM</source>
        <translation>Подключено к %1, ожидание RTCM</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 closed the connection</source>
        <translation>%1: соединение закрыто другой стороной</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Connecting to %1</source>
        <translation>Подключение к %1</translation>
    </message>
</context>
<context>
    <name>gnss::link</name>
    <message>
        <location filename="../protocol/link/recording.cpp" line="+38"/>
        <location line="+16"/>
        <source>Cannot read %1: %2</source>
        <translation>Не удаётся прочитать %1: %2</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Cannot map %1: %2</source>
        <translation>Не удаётся отобразить в память %1: %2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1, line %2: %3</source>
        <translation>%1, строка %2: %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not an index line</source>
        <translation>это не строка индекса</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bad host time</source>
        <translation>неверное время хоста</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>offset %1 is before the previous record&apos;s %2</source>
        <translation>смещение %1 меньше смещения предыдущей записи (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>offset past the end of the data file</source>
        <translation>смещение за концом файла данных</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>bad length</source>
        <translation>неверная длина</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>chunk starts at %1, expected %2</source>
        <translation>блок начинается с %1, ожидалось %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>chunk ends past the end of the data file</source>
        <translation>блок выходит за конец файла данных</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown record &apos;%1&apos;</source>
        <translation>неизвестная запись «%1»</translation>
    </message>
</context>
<context>
    <name>gnss::link::BaudDetector</name>
    <message>
        <location filename="../protocol/link/baud_detector.cpp" line="+30"/>
        <source>Baud detection needs an open serial port</source>
        <translation>Для определения скорости нужен открытый последовательный порт</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Baud detection cancelled</source>
        <translation>Определение скорости отменено</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>No data at any rate (tried %1 baud): check the cable, the port and that the receiver is powered</source>
        <translation>Нет данных ни на одной скорости (проверено: %1 бод): проверьте кабель, порт и питание приёмника</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Data but never a valid sentence or RTCM 3 frame at %1 baud: wrong framing (data bits, parity, stop bits) or the receiver is not sending NMEA or RTCM?</source>
        <translation>Данные есть, но ни одного верного предложения или кадра RTCM 3 на скоростях %1 бод: неверный формат кадра (биты данных, чётность, стоповые биты) или приёмник не передаёт NMEA или RTCM?</translation>
    </message>
</context>
<context>
    <name>gnss::link::CommandQueue</name>
    <message>
        <location filename="../protocol/link/command_queue.cpp" line="+43"/>
        <location line="+203"/>
        <source>accepted</source>
        <translation>принято</translation>
    </message>
    <message>
        <location line="-202"/>
        <source>refused</source>
        <translation>отклонено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed out</source>
        <translation>тайм-аут</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>link lost</source>
        <translation>связь потеряна</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>отменено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sent</source>
        <translation>отправлено</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Too long: %1 characters with its line end; %2 takes at most %3</source>
        <translation>Слишком длинное предложение: %1 символов вместе с концом строки; %2 принимает не более %3</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Not a sentence: %1 (%2)</source>
        <translation>Некорректное сообщение: %1 (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>cancelled before the receiver answered</source>
        <translation>отменено до ответа приёмника</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cancelled before it was sent</source>
        <translation>отменено до отправки</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>not connected: the command was not sent</source>
        <translation>нет подключения: команда не отправлена</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 cannot send commands</source>
        <translation>через %1 нельзя отправлять команды</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>could not write to %1: %2</source>
        <translation>не удалось записать в %1: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>sent; the receiver does not answer this command</source>
        <translation>отправлено; приёмник не отвечает на эту команду</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sent; no known reply to wait for</source>
        <translation>отправлено; ожидаемый ответ неизвестен</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the port now runs at %1 baud; the receiver talks at that rate</source>
        <translation>порт теперь работает на скорости %1 бод; приёмник передаёт на этой скорости</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no valid data at %1 baud after the change; the receiver still talks at %2 baud, so the port is back at %2</source>
        <translation>после смены нет корректных данных на скорости %1 бод; приёмник по-прежнему работает на %2 бод, поэтому порт возвращён на %2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the receiver refused it: %1</source>
        <translation>приёмник отклонил команду: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>accepted; the speed was already %1</source>
        <translation>принято; скорость уже была %1</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>no valid data at %1 baud after the change, nor back at %2 baud: check the receiver and the cable, then detect the baud rate again</source>
        <translation>после смены нет корректных данных ни на скорости %1 бод, ни на прежней %2 бод: проверьте приёмник и кабель, затем снова определите скорость</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>no answer after %n attempt(s)</source>
        <translation>
            <numerusform>нет ответа после %n попытки</numerusform>
            <numerusform>нет ответа после %n попыток</numerusform>
            <numerusform>нет ответа после %n попыток</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the link closed before the answer</source>
        <translation>соединение закрыто до получения ответа</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the link was lost before the answer: %1</source>
        <translation>связь потеряна до получения ответа: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not sent: the link was lost</source>
        <translation>не отправлено: связь потеряна</translation>
    </message>
</context>
<context>
    <name>gnss::link::Connection</name>
    <message>
        <location filename="../protocol/link/connection.cpp" line="+25"/>
        <source>no data for %1 s</source>
        <translation>нет данных %1 с</translation>
    </message>
</context>
<context>
    <name>gnss::link::GpsdTransport</name>
    <message>
        <location filename="../protocol/link/gpsd_transport.cpp" line="+30"/>
        <location line="+3"/>
        <location line="+12"/>
        <source>a gpsd source is HOST[:PORT][/DEVICE], got &apos;%1&apos;</source>
        <translation>источник gpsd задаётся как ХОСТ[:ПОРТ][/УСТРОЙСТВО], получено «%1»</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>gpsd&apos;s port is a number from 1 to 65535, got &apos;%1&apos;</source>
        <translation>порт gpsd — число от 1 до 65535, получено «%1»</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>no answer within %1 s</source>
        <translation>нет ответа за %1 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gpsd did not answer the watch request within %1 s</source>
        <translation>gpsd не ответил на запрос WATCH за %1 с</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>gpsd closed the connection</source>
        <translation>gpsd закрыл соединение</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: gpsd closed the connection</source>
        <translation>%1: gpsd закрыл соединение</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (is gpsd running?)</source>
        <translation>%1 (запущен ли gpsd?)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Не удаётся подключиться к %1: %2</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>this is not gpsd: it did not greet with its VERSION</source>
        <translation>это не gpsd: нет приветствия VERSION</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>gpsd has no device %1 (it has none)</source>
        <translation>у gpsd нет устройства %1 (устройств нет вовсе)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gpsd has no device %1 (it has %2)</source>
        <translation>у gpsd нет устройства %1 (есть: %2)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>gpsd refused: %1</source>
        <translation>gpsd отказал: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: gpsd says: %2</source>
        <translation>%1: gpsd сообщает: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>gpsd at %1</source>
        <translation>gpsd на %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gpsd at %1, %2</source>
        <translation>gpsd на %1, %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gpsd owns the port: commands cannot be sent to a receiver read through gpsd</source>
        <translation>портом владеет gpsd: приёмнику, читаемому через gpsd, нельзя отправлять команды</translation>
    </message>
</context>
<context>
    <name>gnss::link::LinkOpener</name>
    <message>
        <location filename="../protocol/link/link_opener.cpp" line="+19"/>
        <source>%1 (valid NMEA)</source>
        <translation>%1 (корректный NMEA)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (valid RTCM 3)</source>
        <translation>%1 (верный RTCM 3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (no data)</source>
        <translation>%1 (нет данных)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (data, no valid sentence)</source>
        <translation>%1 (данные есть, корректных сообщений нет)</translation>
    </message>
</context>
<context>
    <name>gnss::link::Recorder</name>
    <message>
        <location filename="../protocol/link/recorder.cpp" line="+24"/>
        <location line="+5"/>
        <location line="+83"/>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>link lost: %1</source>
        <translation>связь потеряна: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>link back: %1</source>
        <translation>связь восстановлена: %1</translation>
    </message>
</context>
<context>
    <name>gnss::link::ReplayTransport</name>
    <message>
        <location filename="../protocol/link/replay_transport.cpp" line="+92"/>
        <source>Cannot read %1: %2</source>
        <translation>Не удаётся прочитать %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>permission denied</source>
        <translation>нет прав доступа</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no such file</source>
        <translation>файл не найден</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 has no timestamp index (%2): replay it with sentence times instead</source>
        <translation>У %1 нет индекса времени (%2): воспроизводите его по времени в сообщениях</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>replay of %1</source>
        <translation>воспроизведение %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a recorded log cannot take commands</source>
        <translation>записанный журнал не принимает команды</translation>
    </message>
</context>
<context>
    <name>gnss::link::SerialTransport</name>
    <message>
        <location filename="../protocol/link/serial_transport.cpp" line="+51"/>
        <source>Another program may have it open (a terminal program, gpsd, ModemManager).</source>
        <translation>Возможно, порт открыт другой программой (терминалом, gpsd, ModemManager).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a program</source>
        <translation>неизвестная программа</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Its lock file %1 is left from process %2, which has ended: delete that file.</source>
        <translation>Его файл блокировки %1 остался от процесса %2, который уже завершился: удалите этот файл.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Its lock file %1 names %2 (process %3), which does not have it open: try again, and if it stays, end that program.</source>
        <translation>Его файл блокировки %1 указывает на процесс %3 (%2), у которого порт не открыт: попробуйте ещё раз, а если блокировка останется, завершите эту программу.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (process %2) has it open (lock file %3).</source>
        <translation>Порт открыт: %1, процесс %2 (файл блокировки %3).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Its lock file %1 names %2 (process %3).</source>
        <translation>Его файл блокировки %1 указывает на процесс %3 (%2).</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>You are in the &apos;%1&apos; group that may use it, but this session began before you were added: log out and back in.</source>
        <translation>Вы состоите в группе «%1», которой разрешён доступ, но текущий сеанс начат до вашего добавления в неё: выйдите из системы и войдите снова.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Serial ports are for members of the &apos;%1&apos; group: run `sudo usermod -aG %1 $USER`, then log out and back in.</source>
        <translation>Последовательные порты доступны членам группы «%1»: выполните `sudo usermod -aG %1 $USER`, затем выйдите из системы и войдите снова.</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Cannot open %1: %2</source>
        <translation>Не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 at %2 baud</source>
        <translation>%1 на скорости %2 бод</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1: the device went away (unplugged, powered off or hung up: %2)</source>
        <translation>%1: устройство пропало (отключено, обесточено или линия оборвана: %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>gnss::link::SimulatorTransport</name>
    <message>
        <location filename="../app/common/simulator_transport.cpp" line="+27"/>
        <source>The simulator has no receiver of dialect &apos;%1&apos;</source>
        <translation>В имитаторе нет приёмника с диалектом «%1»</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>simulated %1 receiver at %2 baud</source>
        <translation>имитатор приёмника %1 на скорости %2 бод</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The simulated receiver hung up</source>
        <translation>Имитатор приёмника разорвал связь</translation>
    </message>
</context>
<context>
    <name>gnss::link::TcpTransport</name>
    <message>
        <location filename="../protocol/link/tcp_transport.cpp" line="+19"/>
        <source>Cannot connect to %1: no answer within %2 s</source>
        <translation>Не удаётся подключиться к %1: нет ответа за %2 с</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: the connection was closed by the other side</source>
        <translation>%1: соединение закрыто другой стороной</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Не удаётся подключиться к %1: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>gnss::link::TransportFactory</name>
    <message>
        <location filename="../protocol/link/transport_factory.cpp" line="+29"/>
        <source>a TCP source is HOST:PORT, got &apos;%1&apos;</source>
        <translation>источник TCP задаётся как ХОСТ:ПОРТ, получено «%1»</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>no source given</source>
        <translation>источник не указан</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: this program cannot open such a source</source>
        <translation>%1: программа не умеет открывать такой источник</translation>
    </message>
</context>
<context>
    <name>gnss::link::VendorDetector</name>
    <message>
        <location filename="../protocol/link/vendor_detector.cpp" line="+21"/>
        <source>Vendor detection needs an open link</source>
        <translation>Для определения производителя нужно открытое подключение</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>No valid sentence and no answer to any probe: check the baud rate and that the receiver sends NMEA</source>
        <translation>Нет ни корректных сообщений, ни ответа на запросы: проверьте скорость и то, что приёмник передаёт NMEA</translation>
    </message>
</context>
<context>
    <name>gnss::qualify::Report</name>
    <message>
        <location filename="../protocol/qualify/plots.cpp" line="+127"/>
        <source>cold</source>
        <translation>холодный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warm</source>
        <translation>тёплый</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hot</source>
        <translation>горячий</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Time to first fix, s</source>
        <translation>Время до первого решения, с</translation>
    </message>
    <message>
        <location line="+7"/>
        <location filename="../protocol/qualify/report.cpp" line="+387"/>
        <source>No run has fixed yet</source>
        <translation>Ещё ни один запуск не дал решения</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Horizontal error, %1</source>
        <translation>Горизонтальная ошибка, %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+89"/>
        <source>No positions</source>
        <translation>Нет координат</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Epoch</source>
        <translation>Эпоха</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>horizontal</source>
        <translation>горизонталь</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vertical</source>
        <translation>вертикаль</translation>
    </message>
    <message>
        <location filename="../protocol/qualify/report.cpp" line="-306"/>
        <source>%1 h %2 min %3 s</source>
        <translation>%1 ч %2 мин %3 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 min %2 s</source>
        <translation>%1 мин %2 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+242"/>
        <location line="+1"/>
        <location line="+100"/>
        <source>%1 s</source>
        <translation>%1 с</translation>
    </message>
    <message>
        <location line="-338"/>
        <source>fixed</source>
        <translation>решение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout</source>
        <translation>тайм-аут</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lost</source>
        <translation>связь потеряна</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>mean</source>
        <translation>среднее</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>median</source>
        <translation>медиана</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+306"/>
        <source>P90</source>
        <translation>P90</translation>
    </message>
    <message>
        <location line="-305"/>
        <location line="+247"/>
        <location line="+58"/>
        <source>P95</source>
        <translation>P95</translation>
    </message>
    <message>
        <location line="-304"/>
        <source>max</source>
        <translation>макс.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No fix</source>
        <translation>Нет решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Estimated</source>
        <translation>Счисление</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+390"/>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <location line="-389"/>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+389"/>
        <source>DGNSS</source>
        <translation>DGNSS</translation>
    </message>
    <message>
        <location line="-388"/>
        <location line="+388"/>
        <source>RTK float</source>
        <translation>RTK float</translation>
    </message>
    <message>
        <location line="-387"/>
        <location line="+387"/>
        <source>RTK fixed</source>
        <translation>RTK fixed</translation>
    </message>
    <message>
        <location line="-386"/>
        <source>Manual</source>
        <translation>Заданная позиция</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulator</source>
        <translation>Симулятор</translation>
    </message>
    <message>
        <location line="+162"/>
        <location line="+264"/>
        <source>Receiver qualification report</source>
        <translation>Отчёт о квалификации приёмника</translation>
    </message>
    <message>
        <location line="-242"/>
        <source>Generated %1 by GNSS Workbench</source>
        <translation>Создан %1 программой GNSS Workbench</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Conditions</source>
        <translation>Условия</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Started</source>
        <translation>Начало</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ended</source>
        <translation>Конец</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration</source>
        <translation>Длительность</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Kinds of start</source>
        <translation>Виды старта</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Runs per start</source>
        <translation>Запусков каждого вида</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Timeout</source>
        <translation>Тайм-аут</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pause between runs</source>
        <translation>Пауза между запусками</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>latitude %1°, longitude %2°</source>
        <translation>широта %1°, долгота %2°</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>height %1</source>
        <translation>высота %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>height none</source>
        <translation>высота не задана</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reference point</source>
        <translation>Опорная точка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Location</source>
        <translation>Место</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Comparison</source>
        <translation>Сравнение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time to first 3D fix in seconds, per receiver and kind of start.</source>
        <translation>Время до первого 3D-решения в секундах, по приёмникам и видам старта.</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+21"/>
        <location line="+132"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="-153"/>
        <location line="+58"/>
        <location line="+96"/>
        <source>Start</source>
        <translation>Старт</translation>
    </message>
    <message>
        <location line="-154"/>
        <location line="+58"/>
        <location line="+89"/>
        <source>Runs</source>
        <translation>Запуски</translation>
    </message>
    <message>
        <location line="-147"/>
        <location line="+58"/>
        <source>Fixed</source>
        <translation>С решением</translation>
    </message>
    <message>
        <location line="-58"/>
        <location line="+58"/>
        <source>Mean</source>
        <translation>Среднее</translation>
    </message>
    <message>
        <location line="-58"/>
        <location line="+59"/>
        <source>Median</source>
        <translation>Медиана</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>Time to first fix, all receivers (CDF)</source>
        <translation>Время до первого решения, все приёмники (ФР)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Identity</source>
        <translation>Идентификация</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Model</source>
        <translation>Модель</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>Прошивка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port</source>
        <translation>Порт</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Settings</source>
        <translation>Настройки</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No settings were read</source>
        <translation>Настройки не прочитаны</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setting</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Time to first fix</source>
        <translation>Время до первого решения</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Time to first fix of %1 (CDF)</source>
        <translation>Время до первого решения: %1 (ФР)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+125"/>
        <source>No runs</source>
        <translation>Нет запусков</translation>
    </message>
    <message>
        <location line="-122"/>
        <source>Seconds from the restart to the first 3D fix, of the runs that fixed.</source>
        <translation>Секунды от перезапуска до первого 3D-решения, по запускам с решением.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Timeouts</source>
        <translation>Тайм-ауты</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lost</source>
        <translation>Потеряны</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min</source>
        <translation>Мин.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Max</source>
        <translation>Макс.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Limits</source>
        <translation>Пределы</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Limit</source>
        <translation>Предел</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Measured</source>
        <translation>Измерено</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Итог</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2 ≤ %3 s</source>
        <translation>%1 %2 ≤ %3 с</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no run fixed</source>
        <translation>ни одного решения</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pass</source>
        <translation>выполнен</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>fail</source>
        <translation>не выполнен</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 of %2 limits not met</source>
        <translation>не выполнено пределов: %1 из %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All limits met</source>
        <translation>Все пределы выполнены</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Accuracy against the reference point</source>
        <translation>Точность относительно опорной точки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accuracy about the mean position (no reference point)</source>
        <translation>Точность относительно средней позиции (опорной точки нет)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Positions</source>
        <translation>Координаты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bias east</source>
        <translation>Смещение на восток</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bias north</source>
        <translation>Смещение на север</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bias up</source>
        <translation>Смещение вверх</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Horizontal mean</source>
        <translation>Горизонталь, среднее</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Horizontal median</source>
        <translation>Горизонталь, медиана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP50</source>
        <translation>CEP50</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP95</source>
        <translation>CEP95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2DRMS</source>
        <translation>2DRMS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R95</source>
        <translation>R95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Horizontal max</source>
        <translation>Горизонталь, максимум</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertical mean</source>
        <translation>Вертикаль, среднее</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical median</source>
        <translation>Вертикаль, медиана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical 95 %</source>
        <translation>Вертикаль, 95 %</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Share of epochs within a horizontal distance of the reference point.</source>
        <translation>Доля эпох в пределах горизонтального расстояния от опорной точки.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fix</source>
        <translation>Решение</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Epochs</source>
        <translation>Эпохи</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>≤ %1</source>
        <translation>≤ %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>All</source>
        <translation>Все</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Horizontal error of %1 (histogram)</source>
        <translation>Горизонтальная ошибка: %1 (гистограмма)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Horizontal and vertical error of %1 over time</source>
        <translation>Горизонтальная и вертикальная ошибки: %1 во времени</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Seconds from the restart to the first fix of each kind; the satellites used and the distance from the reference point at the first 3D fix.</source>
        <translation>Секунды от перезапуска до первого решения каждого вида; спутники в решении и расстояние от опорной точки при первом 3D-решении.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Run</source>
        <translation>Запуск</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outcome</source>
        <translation>Итог</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Position</source>
        <translation>Позиция</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D (TTFF)</source>
        <translation>3D (TTFF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Satellites</source>
        <translation>Спутники</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Distance, %1</source>
        <translation>Расстояние, %1</translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+144"/>
        <location line="+3"/>
        <source>Cannot write %1: %2</source>
        <translation>Не удалось записать %1: %2</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>%1: a report is .pdf or .html</source>
        <translation>%1: отчёт бывает .pdf или .html</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: the runs would overwrite the report</source>
        <translation>%1: файл запусков перезаписал бы отчёт</translation>
    </message>
</context>
<context>
    <name>gnss::qualify::TtffCampaign</name>
    <message>
        <location filename="../protocol/qualify/ttff_campaign.cpp" line="+26"/>
        <source>the receiver&apos;s dialect is not known: no restart command to send</source>
        <translation>диалект приёмника неизвестен: нет команды перезапуска</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 has no %2 start (it has: %3)</source>
        <translation>у %1 нет старта «%2» (есть: %3)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message numerus="yes">
        <location line="+169"/>
        <source>Cancelled after %n run(s)</source>
        <translation>
            <numerusform>Отменено после %n прогона</numerusform>
            <numerusform>Отменено после %n прогонов</numerusform>
            <numerusform>Отменено после %n прогонов</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Done: %n run(s)</source>
        <translation>
            <numerusform>Готово: %n прогон</numerusform>
            <numerusform>Готово: %n прогона</numerusform>
            <numerusform>Готово: %n прогонов</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2 of %3</source>
        <translation>%1 %2 из %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: waiting for a 3D fix held %2 s (ephemerides), %3 s</source>
        <translation>%1: ожидание 3D-решения, удерживаемого %2 с (эфемериды), %3 с</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: waiting for the other receivers</source>
        <translation>%1: ожидание остальных приёмников</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: restarting</source>
        <translation>%1: перезапуск</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: waiting for a 3D fix, %2 s</source>
        <translation>%1: ожидание 3D-решения, %2 с</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: done, pausing</source>
        <translation>%1: готово, пауза</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: link lost, waiting for it</source>
        <translation>%1: связь потеряна, ожидание</translation>
    </message>
</context>
<context>
    <name>gnss::serve::NtripCaster</name>
    <message>
        <location filename="../protocol/serve/ntrip_caster.cpp" line="+162"/>
        <source>malformed request: %1</source>
        <translation>неверный запрос: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>no mountpoint %1</source>
        <translation>нет точки подключения %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>wrong user name or password for %1</source>
        <translation>неверные имя пользователя или пароль для %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no credentials for %1</source>
        <translation>нет учётных данных для %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>source table sent</source>
        <translation>таблица источников отправлена</translation>
    </message>
</context>
<context>
    <name>gnss::serve::StreamClients</name>
    <message>
        <location filename="../protocol/serve/stream_clients.cpp" line="+68"/>
        <source>no request within %1 s</source>
        <translation>нет запроса за %1 с</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>closed by the client</source>
        <translation>закрыто клиентом</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>dropped: it did not read its data (%1 KiB waiting)</source>
        <translation>отключён: не читал данные (ожидает %1 КиБ)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the server stopped</source>
        <translation>сервер остановлен</translation>
    </message>
</context>
<context>
    <name>gnss::serve::StreamServer</name>
    <message>
        <location filename="../protocol/serve/stream_server.cpp" line="+39"/>
        <source>dropped by the user</source>
        <translation>отключён пользователем</translation>
    </message>
</context>
<context>
    <name>gnss::session::ReceiverLink</name>
    <message>
        <location filename="../protocol/session/receiver_link.cpp" line="+25"/>
        <location line="+200"/>
        <source>Not connected</source>
        <translation>Нет подключения</translation>
    </message>
    <message>
        <location line="-139"/>
        <source>No source chosen</source>
        <translation>Источник не выбран</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+28"/>
        <location line="+18"/>
        <source>Cannot open %1: %2</source>
        <translation>Не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Connected: %1</source>
        <translation>Подключено: %1</translation>
    </message>
    <message>
        <location line="-81"/>
        <location line="+66"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-136"/>
        <source>%1: detecting the baud rate: trying %2…</source>
        <translation>%1: определение скорости: проверяется %2…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: detecting the baud rate: %2; trying %3…</source>
        <translation>%1: определение скорости: %2; проверяется %3…</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>%1: detecting the baud rate…</source>
        <translation>%1: определение скорости…</translation>
    </message>
    <message>
        <location line="+161"/>
        <source>%1 cannot take commands</source>
        <translation>%1 не принимает команды</translation>
    </message>
    <message>
        <location line="-150"/>
        <source>Baud rate not found: %1</source>
        <translation>Скорость не найдена: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baud rate detected: %1</source>
        <translation>Скорость определена: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1 — trying again in %2 s</source>
        <translation>%1 — повтор через %2 с</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Link lost: %1 — trying again in %2 s</source>
        <translation>Связь потеряна: %1 — повтор через %2 с</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reconnecting to %1 (attempt %2)…</source>
        <translation>Повторное подключение к %1 (попытка %2)…</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Opening %1… %2%</source>
        <translation>Открытие %1… %2%</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Opening %1…</source>
        <translation>Открытие %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting to %1…</source>
        <translation>Подключение к %1…</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Connected: %1 (detected)</source>
        <translation>Подключено: %1 (определено)</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Not connected: nothing was sent</source>
        <translation>Нет подключения: ничего не отправлено</translation>
    </message>
</context>
<context>
    <name>gnss::ui::AccuracyPanel</name>
    <message>
        <location filename="../ui/qualify/accuracy_panel.cpp" line="+31"/>
        <source>LAT,LON[,HEIGHT] — empty: the mean of the positions</source>
        <translation>ШИР,ДОЛ[,ВЫСОТА] — пусто: среднее координат</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A known point in degrees and, for the vertical error, its height above the ellipsoid in metres: 55.7522,37.6156,180.2</source>
        <translation>Известная точка в градусах и, для вертикальной ошибки, её высота над эллипсоидом в метрах: 55.7522,37.6156,180.2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Reference:</source>
        <translation>Опорная точка:</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+83"/>
        <source>No site list</source>
        <translation>Нет списка пунктов</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Sites</source>
        <translation>Пункты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use a site of your site list as the reference, or keep the mean of these positions as a site (a survey-in by the workbench)</source>
        <translation>Взять опорную точку из списка пунктов или сохранить среднее этих координат как пункт (осреднение программой)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>No sites yet (gnss-cli sites add, or save the mean below)</source>
        <translation>Пунктов пока нет (gnss-cli sites add или сохраните среднее ниже)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save the mean as a site…</source>
        <translation>Сохранить среднее как пункт…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as site</source>
        <translation>Сохранить как пункт</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Site name:</source>
        <translation>Имя пункта:</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Statistic</source>
        <translation>Показатель</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Histogram</source>
        <translation>Гистограмма</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over time</source>
        <translation>Во времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The horizontal error&apos;s histogram, or the horizontal and vertical errors epoch by epoch</source>
        <translation>Гистограмма горизонтальной ошибки или горизонтальная и вертикальная ошибки по эпохам</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>No site named %1</source>
        <translation>Нет пункта %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Reference: the site %1</source>
        <translation>Опорная точка: пункт %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No positions to average yet.</source>
        <translation>Координат для осреднения пока нет.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>A site named %1 is already in the list</source>
        <translation>Пункт %1 уже есть в списке</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved the mean of %1 positions as the site %2</source>
        <translation>Среднее %1 координат сохранено как пункт %2</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Positions</source>
        <translation>Координаты</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The reference is not a point: %1</source>
        <translation>Опорная точка задана неверно: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>No positions yet.</source>
        <translation>Координат пока нет.</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%n position(s) against the reference %1, %2</source>
        <translation>
            <numerusform>%n позиция относительно опорной точки %1, %2</numerusform>
            <numerusform>%n позиции относительно опорной точки %1, %2</numerusform>
            <numerusform>%n позиций относительно опорной точки %1, %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n position(s) against their mean %1, %2 (no reference typed)</source>
        <translation>
            <numerusform>%n позиция относительно их среднего %1, %2 (опорная точка не задана)</numerusform>
            <numerusform>%n позиции относительно их среднего %1, %2 (опорная точка не задана)</numerusform>
            <numerusform>%n позиций относительно их среднего %1, %2 (опорная точка не задана)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bias east</source>
        <translation>Смещение на восток</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bias north</source>
        <translation>Смещение на север</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bias up</source>
        <translation>Смещение вверх</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Horizontal mean</source>
        <translation>Горизонталь, среднее</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Horizontal median</source>
        <translation>Горизонталь, медиана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP50</source>
        <translation>CEP50</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP95</source>
        <translation>CEP95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2DRMS</source>
        <translation>2DRMS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R95</source>
        <translation>R95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Horizontal max</source>
        <translation>Горизонталь, максимум</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertical mean</source>
        <translation>Вертикаль, среднее</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical median</source>
        <translation>Вертикаль, медиана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical 95%</source>
        <translation>Вертикаль, 95%</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2%</source>
        <translation>%1: %2%</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Within (all)</source>
        <translation>В пределах (все)</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Within (%1, %n epoch(s))</source>
        <translation>
            <numerusform>В пределах (%1, %n эпоха)</numerusform>
            <numerusform>В пределах (%1, %n эпохи)</numerusform>
            <numerusform>В пределах (%1, %n эпох)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gnss::ui::AttitudeView</name>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="+28"/>
        <source>Attitude</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>Крен</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch</source>
        <translation>Тангаж</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw</source>
        <translation>Рыскание</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Acceleration</source>
        <translation>Ускорение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>North</source>
        <translation>Север</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>East</source>
        <translation>Восток</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Down</source>
        <translation>Вниз</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Time marks (newest first)</source>
        <translation>Метки времени (новые сверху)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Local time</source>
        <translation>Местное время</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Counter</source>
        <translation>Счётчик</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>GPS time of week (s)</source>
        <translation>Время недели GPS (с)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Altitude MSL (%1)</source>
        <translation>Высота над уровнем моря (%1)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>m/s²</source>
        <translation>м/с²</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No time marks yet</source>
        <translation>Меток времени пока нет</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n time mark(s)</source>
        <translation>
            <numerusform>%n метка времени</numerusform>
            <numerusform>%n метки времени</numerusform>
            <numerusform>%n меток времени</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gnss::ui::BaseStationView</name>
    <message>
        <location filename="../ui/base/base_station_view.cpp" line="+38"/>
        <source>base at a set position</source>
        <translation>база в заданной точке</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>base averaging its own position</source>
        <translation>база, осредняющая свои координаты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK rover</source>
        <translation>RTK-ровер</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>autonomous</source>
        <translation>автономный режим</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not read yet</source>
        <translation>ещё не прочитано</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Read</source>
        <translation>Прочитать</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read the base settings from the receiver</source>
        <translation>Прочитать настройки базы из приёмника</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Position of the base</source>
        <translation>Координаты базы</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Survey-in by the workbench</source>
        <translation>Осреднение программой</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Survey-in by the receiver</source>
        <translation>Осреднение приёмником</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Known position</source>
        <translation>Известная точка</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>For minutes</source>
        <translation>Минут</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Until accuracy, m</source>
        <translation>До точности, м</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+381"/>
        <source>Start survey</source>
        <translation>Начать осреднение</translation>
    </message>
    <message>
        <location line="-363"/>
        <source>How far the running mean was from the mean now: horizontally and vertically, a point a second</source>
        <translation>Насколько текущее среднее отличалось от итогового: по горизонтали и по вертикали, точка в секунду</translation>
    </message>
    <message>
        <location line="+13"/>
        <source> min</source>
        <translation> мин</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Averaging time:</source>
        <translation>Время осреднения:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start the receiver&apos;s survey</source>
        <translation>Запустить осреднение в приёмнике</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Makes the receiver a base that averages its own position, with the station, interval and port below</source>
        <translation>Делает приёмник базой, осредняющей свои координаты, с номером станции, интервалом и портом ниже</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Latitude, longitude, height</source>
        <translation>Широта, долгота, высота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ECEF X, Y, Z (m)</source>
        <translation>ECEF X, Y, Z (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Typed as:</source>
        <translation>Формат:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>55°45&apos;04.3&quot;N, 37 37.104E, 166.6</source>
        <translation>55°45&apos;04.3&quot;N, 37 37.104E, 166.6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Degrees as decimals, degrees and minutes or DMS, with N/S/E/W or a sign; the height in metres</source>
        <translation>Градусы с долями, градусы и минуты или ГМС, с N/S/E/W или знаком; высота в метрах</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sites</source>
        <translation>Пункты</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Position:</source>
        <translation>Координаты:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height above sea level (the receiver&apos;s geoid separation is added)</source>
        <translation>Высота над уровнем моря (добавляется высота геоида из приёмника)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Base settings</source>
        <translation>Настройки базы</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> m</source>
        <translation> м</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From the mark up to the antenna reference point (a known position)</source>
        <translation>От марки до опорной точки антенны (для известной точки)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Antenna height:</source>
        <translation>Высота антенны:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Station id:</source>
        <translation>Номер станции:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Observables:</source>
        <translation>Измерения:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RTCM on:</source>
        <translation>RTCM через:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to the receiver&apos;s flash once verified</source>
        <translation>Сохранить во флэш-память приёмника после проверки</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set base</source>
        <translation>Задать базу</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as site…</source>
        <translation>Сохранить как пункт…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep the survey&apos;s result (or the position typed) in the site list</source>
        <translation>Сохранить результат осреднения (или введённую точку) в списке пунктов</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Asking the receiver to average its position…</source>
        <translation>Приёмнику отправлена команда осреднять координаты…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No sites yet</source>
        <translation>Пунктов пока нет</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>No receiver whose settings are known: a base station needs one that can be a base (the NV08C-RTK), identified on a link that takes commands.</source>
        <translation>Нет приёмника с известными настройками: для базовой станции нужен приёмник, который может быть базой (NV08C-RTK), опознанный на линии, принимающей команды.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The %1 cannot be a base station: its settings have no base mode.</source>
        <translation>%1 не может быть базовой станцией: в его настройках нет режима базы.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>as it is</source>
        <translation>как есть</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>as they are</source>
        <translation>как есть</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the ports as they are</source>
        <translation>порты как есть</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>port %1 (%2)</source>
        <translation>порт %1 (%2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This receiver does not average its own position.</source>
        <translation>Этот приёмник не осредняет свои координаты.</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+210"/>
        <source>Waiting for the operation in progress on the receiver&apos;s settings to end; the base is set then.</source>
        <translation>Ждём окончания текущей операции с настройками приёмника; базовая станция будет задана после неё.</translation>
    </message>
    <message>
        <location line="-196"/>
        <source>%1, %2: %3 (%4)</source>
        <translation>%1, %2: %3 (%4)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Every value was already in force.</source>
        <translation>Все значения уже действовали.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Saved to flash.</source>
        <translation>Сохранено во флэш-память.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Not saved to flash.</source>
        <translation>Во флэш-память не сохранено.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Base settings verified.</source>
        <translation>Настройки базы проверены.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Base settings not all verified.</source>
        <translation>Не все настройки базы подтверждены.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The receiver averaged its position: %1</source>
        <translation>Приёмник осреднил координаты: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Survey-in done: accuracy %1</source>
        <translation>Осреднение завершено: точность %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The receiver averages its position: %1 s left</source>
        <translation>Приёмник осредняет координаты: осталось %1 с</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waiting for the receiver&apos;s averaged position…</source>
        <translation>Ожидание осреднённых координат от приёмника…</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Role: %1</source>
        <translation>Роль: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position: %1 %2, %3 (ECEF %4)</source>
        <translation>Координаты: %1 %2, %3 (ECEF %4)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>station %1</source>
        <translation>станция %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>observables: %1</source>
        <translation>измерения: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RTCM on port %1</source>
        <translation>RTCM через порт %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>From its own fix: %1</source>
        <translation>От собственного решения: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The base position is %1 from the receiver&apos;s own fix, past its threshold of %2: it sends no corrections.</source>
        <translation>Координаты базы в %1 от собственного решения приёмника, больше порога %2: поправки не передаются.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Waiting for the receiver&apos;s fixes…</source>
        <translation>Ожидание решений приёмника…</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%n position(s) in %1 s. Mean %2 %3, %4.
σ east %5, north %6, up %7; the mean known to %8.</source>
        <translation>
            <numerusform>%n позиция за %1 с. Среднее %2 %3, %4.
σ восток %5, север %6, верх %7; среднее известно с точностью %8.</numerusform>
            <numerusform>%n позиции за %1 с. Среднее %2 %3, %4.
σ восток %5, север %6, верх %7; среднее известно с точностью %8.</numerusform>
            <numerusform>%n позиций за %1 с. Среднее %2 %3, %4.
σ восток %5, север %6, верх %7; среднее известно с точностью %8.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Stop survey</source>
        <translation>Остановить осреднение</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The receiver reported its set position: it now reports its own.</source>
        <translation>Приёмник выдавал заданные координаты базы: теперь он выдаёт собственные.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No survey yet: start one first.</source>
        <translation>Осреднения ещё не было: сначала запустите его.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The receiver finds its position itself: start its survey instead.</source>
        <translation>Приёмник определяет координаты сам: запустите его осреднение.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Expected X, Y, Z in metres.</source>
        <translation>Ожидаются X, Y, Z в метрах.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The receiver has not given its geoid separation yet.</source>
        <translation>Приёмник ещё не сообщил высоту геоида.</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Save as site</source>
        <translation>Сохранить как пункт</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Site name:</source>
        <translation>Имя пункта:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Site &apos;%1&apos; saved</source>
        <translation>Пункт «%1» сохранён</translation>
    </message>
</context>
<context>
    <name>gnss::ui::ChartsView</name>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="+111"/>
        <source>Series</source>
        <translation>Ряды</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Window</source>
        <translation>Окно</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> min</source>
        <translation> мин</translation>
    </message>
    <message>
        <location line="+191"/>
        <source>minutes before the latest epoch</source>
        <translation>минуты до последней эпохи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>seconds before the latest epoch</source>
        <translation>секунды до последней эпохи</translation>
    </message>
</context>
<context>
    <name>gnss::ui::Cn0MapView</name>
    <message>
        <location filename="../ui/views/cn0_map_view.cpp" line="+33"/>
        <source>Mean C/N0</source>
        <translation>Средний C/N0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Count</source>
        <translation>Число</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>N</source>
        <translation>С</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 dB-Hz</source>
        <translation>%1 дБГц</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%n epoch(s)</source>
        <translation>
            <numerusform>%n эпоха</numerusform>
            <numerusform>%n эпохи</numerusform>
            <numerusform>%n эпох</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gnss::ui::ComparePlot</name>
    <message>
        <location filename="../ui/views/compare_plot.cpp" line="+47"/>
        <source>Two or more receivers are compared here.</source>
        <translation>Здесь сравниваются два приёмника и более.</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>N ↑  E →  ±%1 m</source>
        <translation>С ↑  В →  ±%1 м</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>horizontal (solid), up (dashed): %1 … %2 m</source>
        <translation>в плане (сплошная), по высоте (пунктир): %1 … %2 м</translation>
    </message>
</context>
<context>
    <name>gnss::ui::CompareView</name>
    <message>
        <location filename="../ui/views/compare_view.cpp" line="+55"/>
        <source>The numbers, the plots and the export are over this window</source>
        <translation>Числа, графики и экспорт — за это окно</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>last %n minute(s)</source>
        <translation>
            <numerusform>последняя %n минута</numerusform>
            <numerusform>последние %n минуты</numerusform>
            <numerusform>последние %n минут</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The receiver the plots draw against the reference</source>
        <translation>Приёмник, который графики сравнивают с опорным</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Export</source>
        <translation>Экспорт</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CSV, one row per matched epoch...</source>
        <translation>CSV, строка на каждую совпавшую эпоху...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>JSON, the numbers over the window...</source>
        <translation>JSON, числа за окно...</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Summary</source>
        <translation>Сводка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Signals</source>
        <translation>Сигналы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plots</source>
        <translation>Графики</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Connect two or more receivers to compare them (Add receiver)</source>
        <translation>Подключите два приёмника и более, чтобы сравнить их (Добавить приёмник)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 matched epochs (%2 since the start)</source>
        <translation>Совпавших эпох: %1 (с начала: %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Receivers are matched epoch by epoch on UTC time; each difference is a receiver minus the first, %1.</source>
        <translation>Приёмники сопоставляются по эпохам по времени UTC; каждая разность — приёмник минус первый, %1.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Fix %1 (share of epochs)</source>
        <translation>Решение %1 (доля эпох)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 mean (m)</source>
        <translation>%1, среднее (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 median (m)</source>
        <translation>%1, медиана (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 p95 (m)</source>
        <translation>%1, p95 (м)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>East</source>
        <translation>Восток</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>North</source>
        <translation>Север</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation>Высота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Horizontal</source>
        <translation>В плане</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CEP50 (m)</source>
        <translation>CEP50 (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP95 (m)</source>
        <translation>CEP95 (м)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>C/N0 difference, mean (dB)</source>
        <translation>Разность C/N0, среднее (дБ)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C/N0 difference, p95 (dB)</source>
        <translation>Разность C/N0, p95 (дБ)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>C/N0 %1: mean, p95 (dB), satellites</source>
        <translation>C/N0 %1: среднее, p95 (дБ), спутники</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2 (%3)</source>
        <translation>%1, %2 (%3)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Only in the reference</source>
        <translation>Только у опорного</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only in this one</source>
        <translation>Только у этого</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Satellite</source>
        <translation>Спутник</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Signal</source>
        <translation>Сигнал</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (dB-Hz)</source>
        <translation>%1 (дБГц)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 − %2</source>
        <translation>%1 − %2</translation>
    </message>
</context>
<context>
    <name>gnss::ui::ConsoleView</name>
    <message>
        <location filename="../ui/views/console_view.cpp" line="+35"/>
        <source>Filter by address (e.g. GGA|PNVG)</source>
        <translation>Фильтр по адресу (например, GGA|PNVG)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the raw bytes received, including binary data</source>
        <translation>Показать принятые байты, включая двоичные данные</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Clear</source>
        <translation>Очистить</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Send</source>
        <translation>Отправить</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Sending is off: %1.</source>
        <translation>Отправка отключена: %1.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>No commands: %1</source>
        <translation>Команды недоступны: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Command to send (the checksum is added)</source>
        <translation>Команда для отправки (контрольная сумма добавляется)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command to send, e.g. %1 (the checksum is added)</source>
        <translation>Команда для отправки, например %1 (контрольная сумма добавляется)</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Not sent: %1</source>
        <translation>Не отправлено: %1</translation>
    </message>
</context>
<context>
    <name>gnss::ui::CoordinateEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="+253"/>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+8"/>
        <source> m</source>
        <translation> м</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Height above the WGS-84 ellipsoid</source>
        <translation>Высота над эллипсоидом WGS-84</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>N</source>
        <translation>с. ш.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>S</source>
        <translation>ю. ш.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E</source>
        <translation>в. д.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>W</source>
        <translation>з. д.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ellipsoidal height</source>
        <translation>Высота над эллипсоидом</translation>
    </message>
</context>
<context>
    <name>gnss::ui::CorrectionsView</name>
    <message>
        <location filename="../ui/views/corrections_view.cpp" line="+59"/>
        <source>RTK fixed</source>
        <translation>RTK fixed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK float</source>
        <translation>RTK float</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>differential</source>
        <translation>дифференциальный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>autonomous</source>
        <translation>автономный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no fix</source>
        <translation>нет решения</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Source</source>
        <translation>Источник</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>NTRIP caster</source>
        <translation>NTRIP-кастер</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP stream (a base&apos;s raw RTCM)</source>
        <translation>Поток TCP (RTCM напрямую от базы)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>Тип</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>caster.example.org</source>
        <translation>caster.example.org</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Host and port</source>
        <translation>Хост и порт</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Mountpoint</source>
        <translation>Точка подключения</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>User</source>
        <translation>Пользователь</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+90"/>
        <source>not stored</source>
        <translation>не сохраняется</translation>
    </message>
    <message>
        <location line="-89"/>
        <source>Password</source>
        <translation>Пароль</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remember the password in the system keychain</source>
        <translation>Запомнить пароль в системной связке ключей</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>NTRIP 2 (HTTP/1.1)</source>
        <translation>NTRIP 2 (HTTP/1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NTRIP 1</source>
        <translation>NTRIP 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol</source>
        <translation>Протокол</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+146"/>
        <source>Start</source>
        <translation>Запустить</translation>
    </message>
    <message>
        <location line="-142"/>
        <source>Not started</source>
        <translation>Не запущено</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Received</source>
        <translation>Принято</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Count</source>
        <translation>Количество</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rate, /s</source>
        <translation>Частота, /с</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Age, s</source>
        <translation>Возраст, с</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Meaning</source>
        <translation>Описание</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Correction age, s (last 10 min)</source>
        <translation>Возраст поправок, с (последние 10 мин)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>kept in the keychain</source>
        <translation>хранится в связке ключей</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Give the host of the corrections.</source>
        <translation>Укажите хост источника поправок.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Give only the host name or address here: the user name and the password have their own fields.</source>
        <translation>Здесь укажите только имя или адрес хоста: для имени пользователя и пароля есть свои поля.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&apos;%1&apos; is not a host name or address.</source>
        <translation>«%1» — не имя хоста и не адрес.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The port is 1 to 65535.</source>
        <translation>Порт — число от 1 до 65535.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Give the mountpoint.</source>
        <translation>Укажите точку подключения.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; is not a mountpoint name.</source>
        <translation>«%1» — недопустимое имя точки подключения.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A password was given without a user name.</source>
        <translation>Пароль указан без имени пользователя.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Stop</source>
        <translation>Остановить</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>%1 B/s, %2 messages, %3 CRC errors, %4 bytes not RTCM; correction age %5</source>
        <translation>%1 Б/с, сообщений: %2, ошибок CRC: %3, байт не RTCM: %4; возраст поправок: %5</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 s</source>
        <translation>%1 с</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, %2, %3</source>
        <translation>%1, %2, %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ECEF %1, %2, %3 m</source>
        <translation>ECEF %1, %2, %3 м</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Base station %1 (%2): %3; from the receiver&apos;s own fix %4</source>
        <translation>Базовая станция %1 (%2): %3; от собственного решения приёмника %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station %1 (%2): %3; distance to the rover %4</source>
        <translation>Базовая станция %1 (%2): %3; расстояние до ровера %4</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 from the position set on %2</source>
        <translation>%1 от координат, заданных на %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Base station: not yet received (1005/1006)</source>
        <translation>Базовая станция: данных пока нет (1005/1006)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Forwarded to the receiver: %1 frames (%2 bytes); dropped %3</source>
        <translation>Передано в приёмник кадров: %1 (байт: %2); отброшено: %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not forwarded: no receiver connected</source>
        <translation>Не передаётся: приёмник не подключён</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fix: %1; RTK mode %2; correction age %3</source>
        <translation>Решение: %1; режим RTK: %2; возраст поправок: %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; RTCM messages received %1, bad %2</source>
        <translation>; принято сообщений RTCM: %1, с ошибками: %2</translation>
    </message>
</context>
<context>
    <name>gnss::ui::DeviationView</name>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="+84"/>
        <source>No position yet</source>
        <translation>Координат пока нет</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>East (%1)</source>
        <translation>Восток (%1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>North (%1)</source>
        <translation>Север (%1)</translation>
    </message>
    <message>
        <location line="+35"/>
        <location line="+109"/>
        <source>CEP50</source>
        <translation>CEP50</translation>
    </message>
    <message>
        <location line="-108"/>
        <location line="+109"/>
        <source>CEP95</source>
        <translation>CEP95</translation>
    </message>
    <message>
        <location line="-108"/>
        <location line="+109"/>
        <source>2DRMS</source>
        <translation>2DRMS</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Reference</source>
        <translation>Опорная точка</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Centre on a known position instead of the mean of the positions</source>
        <translation>Центрировать по известной точке, а не по среднему положению</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>latitude, e.g. 55.7512 N</source>
        <translation>широта, например 55.7512 N</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>longitude, e.g. 37.6181 E</source>
        <translation>долгота, например 37.6181 E</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>How many of the latest positions are kept</source>
        <translation>Сколько последних положений хранить</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+24"/>
        <source>Points</source>
        <translation>Точки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centre:</source>
        <translation>Центр:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mean offset:</source>
        <translation>Среднее смещение:</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>Reference not used: type degrees such as 55.75123456 N and 37.61812345 E (or signed, -33.9 for south). Centred on the mean.</source>
        <translation>Опорная точка не используется: введите градусы, например 55.75123456 N и 37.61812345 E (или со знаком: -33.9 для южной широты). Центр — по среднему положению.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>reference %1, %2</source>
        <translation>опорная точка %1, %2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mean %1, %2</source>
        <translation>среднее %1, %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 east, %2 north</source>
        <translation>%1 на восток, %2 на север</translation>
    </message>
</context>
<context>
    <name>gnss::ui::FixView</name>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="+31"/>
        <source>Degrees</source>
        <translation>Градусы</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deg min sec</source>
        <translation>Град. мин. сек.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deg min</source>
        <translation>Град. мин.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How coordinates are written (also in Preferences)</source>
        <translation>Как записываются координаты (также в «Параметрах»)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude (sea level)</source>
        <translation>Высота (над уровнем моря)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude (ellipsoid)</source>
        <translation>Высота (над эллипсоидом)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Satellites used / in view</source>
        <translation>Спутники: в решении / видимые</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDOP / HDOP / VDOP</source>
        <translation>PDOP / HDOP / VDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Course</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Age of corrections</source>
        <translation>Возраст поправок</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>No data</source>
        <translation>Нет данных</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>s</source>
        <translation>с</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogChartsPanel</name>
    <message>
        <location filename="../ui/logview/whole_log_panels.cpp" line="+24"/>
        <source>wheel: zoom · drag: pan · click: go there</source>
        <translation>колесо: масштаб · перетаскивание: сдвиг · щелчок: перейти</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Whole log</source>
        <translation>Весь журнал</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogEventsView</name>
    <message>
        <location filename="../ui/logview/log_events_view.cpp" line="+39"/>
        <source>Show:</source>
        <translation>Показать:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>All events</source>
        <translation>Все события</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export CSV…</source>
        <translation>Экспорт CSV…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Event</source>
        <translation>Событие</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Details</source>
        <translation>Подробности</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Fix change</source>
        <translation>Смена решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data gap</source>
        <translation>Пропуск данных</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link lost</source>
        <translation>Потеря связи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Checksum errors</source>
        <translation>Ошибки контрольной суммы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time jump</source>
        <translation>Скачок времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Receiver change</source>
        <translation>Смена приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time mark</source>
        <translation>Метка времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jamming</source>
        <translation>Помехи</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>standard NMEA</source>
        <translation>стандартный NMEA</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no epochs for %1 s</source>
        <translation>нет эпох в течение %1 с</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>time went back %1 s</source>
        <translation>время ушло назад на %1 с</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>checksum errors: %1, over epochs: %2</source>
        <translation>ошибок контрольной суммы: %1, в эпохах: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 sentences (after %2)</source>
        <translation>сообщения %1 (после %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 sentences</source>
        <translation>сообщения %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>time mark</source>
        <translation>метка времени</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>jamming detected</source>
        <translation>обнаружены помехи</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>jamming cleared</source>
        <translation>помехи пропали</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>station %1 (was %2)</source>
        <translation>станция %1 (была %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>station %1</source>
        <translation>станция %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Epoch %1</source>
        <translation>Эпоха %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No log open</source>
        <translation>Журнал не открыт</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Indexing…</source>
        <translation>Индексация…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No events: the fix never changed, and there were no gaps, resets or checksum errors</source>
        <translation>Событий нет: решение не менялось, пропусков, сбросов и ошибок контрольной суммы не было</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Events: %1; click one to go there</source>
        <translation>Событий: %1; щёлкните событие, чтобы перейти к нему</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogLinesModel</name>
    <message>
        <location filename="../ui/logview/log_lines_model.cpp" line="+262"/>
        <source>The filter is not a valid expression: %1</source>
        <translation>Фильтр — недопустимое регулярное выражение: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filtering the log&apos;s lines…</source>
        <translation>Отбор строк журнала…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The first %L1 lines whose address matches (a filter keeps no more)</source>
        <translation>Первые %L1 строк с подходящим адресом (больше фильтр не хранит)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lines that match: %L1</source>
        <translation>Подходящих строк: %L1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · shown: %L1 to %L2, around the cursor</source>
        <translation> · показаны строки с %L1 по %L2, вокруг курсора</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Counting the log&apos;s lines…</source>
        <translation>Подсчёт строк журнала…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lines %L1 to %L2 of %L3, around the cursor</source>
        <translation>Строки с %L1 по %L2 из %L3, вокруг курсора</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>not a sentence</source>
        <translation>не сообщение NMEA</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Checksum %1, computed %2</source>
        <translation>Контрольная сумма %1, вычислена %2</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogPlot</name>
    <message>
        <location filename="../ui/logview/log_plot.cpp" line="+48"/>
        <source>Altitude</source>
        <translation>Высота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Satellites used</source>
        <translation>Спутников в решении</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HDOP</source>
        <translation>HDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mean SNR</source>
        <translation>Средний SNR</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>dB-Hz</source>
        <translation>дБГц</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Indexing…</source>
        <translation>Индексация…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No log open</source>
        <translation>Журнал не открыт</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>The log has no %1</source>
        <translation>В журнале нет величины «%1»</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogSummaryView</name>
    <message>
        <location filename="../ui/logview/log_summary_view.cpp" line="+26"/>
        <source>%1 s</source>
        <translation>%1 с</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Spread of the epochs standing still</source>
        <translation>Разброс только для эпох без движения</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CEP and 2DRMS of the epochs whose speed is under 0.5 m/s (all epochs when there are none)</source>
        <translation>CEP и 2DRMS по эпохам со скоростью меньше 0,5 м/с (по всем эпохам, если таких нет)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save JSON…</source>
        <translation>Сохранить JSON…</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Range</source>
        <translation>Диапазон</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accuracy</source>
        <translation>Точность</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Indexing…</source>
        <translation>Индексация…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No log open</source>
        <translation>Журнал не открыт</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Selected range: epochs %1 to %2</source>
        <translation>Выбранный интервал: эпохи с %1 по %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Whole log: epochs %1 to %2</source>
        <translation>Весь журнал: эпохи с %1 по %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Epochs</source>
        <translation>Эпох</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration</source>
        <translation>Длительность</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (availability)</source>
        <translation>%1 (доступность)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 % (%2 epochs)</source>
        <translation>%1 % (эпох: %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time to first fix</source>
        <translation>Время до первого решения</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time to RTK fixed</source>
        <translation>Время до RTK fixed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data gaps</source>
        <translation>Пропуски данных</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1, the longest %2 (before epoch %3)</source>
        <translation>%1, самый долгий %2 (перед эпохой %3)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time jumps</source>
        <translation>Скачки времени</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Checksum errors</source>
        <translation>Ошибки контрольной суммы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Epochs with junk</source>
        <translation>Эпохи с мусором</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Positions</source>
        <translation>Координат</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 (standing still)</source>
        <translation>%1 (без движения)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mean position</source>
        <translation>Среднее положение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Mean altitude</source>
        <translation>Средняя высота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP50</source>
        <translation>CEP50</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CEP95</source>
        <translation>CEP95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2DRMS</source>
        <translation>2DRMS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max HDOP</source>
        <translation>Наибольший HDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (epoch %2)</source>
        <translation>%1 (эпоха %2)</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogTrack</name>
    <message>
        <location filename="../ui/logview/log_track.cpp" line="+165"/>
        <source>Indexing…</source>
        <translation>Индексация…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No positions</source>
        <translation>Нет координат</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Origin %1, %2%3</source>
        <translation>Начало отсчёта %1, %2%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (reference)</source>
        <translation> (опорная точка)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> (mean)</source>
        <translation> (среднее)</translation>
    </message>
</context>
<context>
    <name>gnss::ui::LogTrackPanel</name>
    <message>
        <location filename="../ui/logview/whole_log_panels.cpp" line="+12"/>
        <source>Reference:</source>
        <translation>Опорная точка:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the mean position</source>
        <translation>среднее положение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude, longitude in degrees (55.75, 37.62); empty for the mean of the log&apos;s positions</source>
        <translation>Широта, долгота в градусах (55.75, 37.62); пусто — среднее по координатам журнала</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit</source>
        <translation>Вписать</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Write the reference as latitude, longitude in degrees: 55.75, 37.62</source>
        <translation>Запишите опорную точку как широту, долготу в градусах: 55.75, 37.62</translation>
    </message>
</context>
<context>
    <name>gnss::ui::MessageStatsModel</name>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="+60"/>
        <source>Address</source>
        <translation>Адрес</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Count</source>
        <translation>Количество</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate (Hz)</source>
        <translation>Частота (Гц)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last seen (local time)</source>
        <translation>Последнее (местное время)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last seen (UTC)</source>
        <translation>Последнее (UTC)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Checksum errors</source>
        <translation>Ошибки КС</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Decode errors</source>
        <translation>Ошибки разбора</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unknown</source>
        <translation>Неизвестные</translation>
    </message>
</context>
<context>
    <name>gnss::ui::QualificationView</name>
    <message>
        <location filename="../ui/qualify/qualification_view.cpp" line="+32"/>
        <source>cold</source>
        <translation>холодный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warm</source>
        <translation>тёплый</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hot</source>
        <translation>горячий</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>fixed</source>
        <translation>решение</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed out</source>
        <translation>тайм-аут</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>link lost</source>
        <translation>связь потеряна</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The selected receiver</source>
        <translation>Выбранный приёмник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every receiver, at once</source>
        <translation>Все приёмники сразу</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On:</source>
        <translation>Где:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cold</source>
        <translation>Холодный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warm</source>
        <translation>Тёплый</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hot</source>
        <translation>Горячий</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Starts:</source>
        <translation>Старты:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Runs of each:</source>
        <translation>Запусков каждого:</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+3"/>
        <location line="+2"/>
        <source> s</source>
        <translation> с</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>A run without a 3D fix after this long is counted as a timeout</source>
        <translation>Запуск без 3D-решения за это время считается тайм-аутом</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout:</source>
        <translation>Тайм-аут:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause:</source>
        <translation>Пауза:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Before a warm or hot start the receiver holds a 3D fix this long, so that it has its ephemerides</source>
        <translation>Перед тёплым или горячим стартом приёмник держит 3D-решение столько времени, чтобы получить эфемериды</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hold fix:</source>
        <translation>Держать решение:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cold:mean&lt;=60, hot:p95&lt;=15</source>
        <translation>cold:mean&lt;=60, hot:p95&lt;=15</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limits to pass, separated by commas: START:STATISTIC&lt;=SECONDS, the statistic one of mean, median, p90, p95, max</source>
        <translation>Пределы через запятую: СТАРТ:ПОКАЗАТЕЛЬ&lt;=СЕКУНДЫ (cold, warm, hot; mean, median, p90, p95, max)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Limits:</source>
        <translation>Пределы:</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+35"/>
        <location line="+9"/>
        <source>Start</source>
        <translation>Старт</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save report…</source>
        <translation>Сохранить отчёт…</translation>
    </message>
    <message>
        <location line="-41"/>
        <source>No campaign yet.</source>
        <translation>Испытаний ещё не было.</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Runs done of the campaign&apos;s runs</source>
        <translation>Выполнено запусков из всех запусков серии</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+9"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="-9"/>
        <location line="+13"/>
        <source>Runs</source>
        <translation>Запуски</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Fixed</source>
        <translation>С решением</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeouts</source>
        <translation>Тайм-ауты</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lost</source>
        <translation>Потеряны</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mean</source>
        <translation>Среднее</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Median</source>
        <translation>Медиана</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P90</source>
        <translation>P90</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>P95</source>
        <translation>P95</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min</source>
        <translation>Мин.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Max</source>
        <translation>Макс.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limits</source>
        <translation>Пределы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Times to a 3D fix in seconds, of the runs that fixed</source>
        <translation>Время до 3D-решения в секундах, по запускам с решением</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Results</source>
        <translation>Итоги</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CDF</source>
        <translation>ФР</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run</source>
        <translation>Запуск</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outcome</source>
        <translation>Итог</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position</source>
        <translation>Позиция</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>3D (TTFF)</source>
        <translation>3D (TTFF)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>DGNSS</source>
        <translation>DGNSS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTK float</source>
        <translation>RTK float</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RTK fixed</source>
        <translation>RTK fixed</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Satellites</source>
        <translation>Спутники</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance</source>
        <translation>Расстояние</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Accuracy</source>
        <translation>Точность</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Run %1 of %2; about %3 min left</source>
        <translation>Запуск %1 из %2; осталось около %3 мин</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 %2 ≤ %3 s: %4</source>
        <translation>%1 %2 ≤ %3 с: %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pass</source>
        <translation>выполнен</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FAIL</source>
        <translation>НЕ ВЫПОЛНЕН</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Choose at least one kind of start.</source>
        <translation>Выберите хотя бы один вид старта.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>A limit is not understood: %1</source>
        <translation>Предел не распознан: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The reference point (Accuracy tab) is not a point.</source>
        <translation>Опорная точка (вкладка «Точность») задана неверно.</translation>
    </message>
</context>
<context>
    <name>gnss::ui::ReceiverInfoView</name>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="+69"/>
        <source>Item</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Receiver: not identified yet</source>
        <translation>Приёмник: ещё не опознан</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;b&gt;%1 %2&lt;/b&gt;&lt;br&gt;Firmware: %3%4</source>
        <translation>&lt;b&gt;%1 %2&lt;/b&gt;&lt;br&gt;Прошивка: %3%4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&lt;br&gt;Hardware: %1</source>
        <translation>&lt;br&gt;Аппаратура: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jamming: not reported</source>
        <translation>Помехи: не сообщаются</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Jamming: DETECTED</source>
        <translation>Помехи: ОБНАРУЖЕНЫ</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jamming: none detected</source>
        <translation>Помехи: не обнаружены</translation>
    </message>
</context>
<context>
    <name>gnss::ui::ReceiverSession</name>
    <message>
        <location filename="../ui/models/receiver_session.cpp" line="+67"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>gnss::ui::RtkView</name>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="+53"/>
        <source>This receiver has not reported RTK information.</source>
        <translation>Приёмник не сообщал сведений RTK.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Mode:</source>
        <translation>Режим:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Alarm when corrections are older than</source>
        <translation>Тревога, если поправки старше</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> s</source>
        <translation> с</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Correction age</source>
        <translation>Возраст поправок</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Distance to base</source>
        <translation>Расстояние до базы</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Base station id</source>
        <translation>Номер базовой станции</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RTCM messages</source>
        <translation>Сообщения RTCM</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RTCM good</source>
        <translation>RTCM без ошибок</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTCM errors</source>
        <translation>Ошибки RTCM</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baseline base → rover</source>
        <translation>Базовая линия база → ровер</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+19"/>
        <source>North</source>
        <translation>Север</translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+19"/>
        <source>East</source>
        <translation>Восток</translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+19"/>
        <source>Vertical</source>
        <translation>Вертикаль</translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+11"/>
        <source>Length</source>
        <translation>Длина</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Course</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+5"/>
        <source>Pitch</source>
        <translation>Тангаж</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Heading (antenna baseline)</source>
        <translation>Курс (линия антенн)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+22"/>
        <source>Heading</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Standard deviations</source>
        <translation>СКО</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height</source>
        <translation>Высота</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity north</source>
        <translation>Скорость на север</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Velocity east</source>
        <translation>Скорость на восток</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Velocity up</source>
        <translation>Скорость вверх</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Receiver DOPs</source>
        <translation>Геометрические факторы приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GDOP</source>
        <translation>GDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDOP</source>
        <translation>PDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HDOP</source>
        <translation>HDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VDOP</source>
        <translation>VDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TDOP</source>
        <translation>TDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NDOP</source>
        <translation>NDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EDOP</source>
        <translation>EDOP</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Autonomous</source>
        <translation>Автономный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential</source>
        <translation>Дифференциальный</translation>
    </message>
    <message>
        <location line="-117"/>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>Correction age: %1</source>
        <translation>Возраст поправок: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Corrections too old: %1 s &gt; %2 s</source>
        <translation>Поправки устарели: %1 с &gt; %2 с</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Corrections OK: %1 s</source>
        <translation>Поправки в норме: %1 с</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SatelliteModel</name>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="+62"/>
        <source>yes</source>
        <translation>да</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>нет</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>System</source>
        <translation>Система</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Satellite</source>
        <translation>Спутник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Signal</source>
        <translation>Сигнал</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Elev. (°)</source>
        <translation>Угол места (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Azim. (°)</source>
        <translation>Азимут (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SNR (dB-Hz)</source>
        <translation>С/Ш (дБГц)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Used</source>
        <translation>В решении</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last seen (UTC)</source>
        <translation>Последнее (UTC)</translation>
    </message>
</context>
<context>
    <name>gnss::ui::ServeView</name>
    <message>
        <location filename="../ui/serve/serve_view.cpp" line="+29"/>
        <source>Listening on %1: other computers can connect.</source>
        <translation>Приём подключений на %1: могут подключаться другие компьютеры.</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>NTRIP caster</source>
        <translation>NTRIP-кастер</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>127.0.0.1: this computer only; 0.0.0.0: every network it is on</source>
        <translation>127.0.0.1 — только этот компьютер; 0.0.0.0 — все его сети</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>0: any free port</source>
        <translation>0 — любой свободный порт</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+39"/>
        <source>Listen on:</source>
        <translation>Адрес и порт:</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>no password</source>
        <translation>без пароля</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>password</source>
        <translation>пароль</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>User:</source>
        <translation>Пользователь:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stream</source>
        <translation>Поток</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+40"/>
        <source>Mountpoint</source>
        <translation>Точка подключения</translation>
    </message>
    <message>
        <location line="-35"/>
        <location line="+126"/>
        <source>Start caster</source>
        <translation>Запустить кастер</translation>
    </message>
    <message>
        <location line="-119"/>
        <source>Share a receiver (raw TCP)</source>
        <translation>Раздать приёмник (TCP как есть)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Receiver:</source>
        <translation>Приёмник:</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+112"/>
        <source>Start sharing</source>
        <translation>Начать раздачу</translation>
    </message>
    <message>
        <location line="-103"/>
        <source>Clients</source>
        <translation>Клиенты</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Server</source>
        <translation>Сервер</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Address</source>
        <translation>Адрес</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>User</source>
        <translation>Пользователь</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Since</source>
        <translation>Подключён в</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Sent</source>
        <translation>Отправлено</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Drop client</source>
        <translation>Отключить клиента</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnect the selected client now (it may connect again)</source>
        <translation>Отключить выбранного клиента сейчас (он может подключиться снова)</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Stop caster</source>
        <translation>Остановить кастер</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Stop sharing</source>
        <translation>Остановить раздачу</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="-41"/>
        <source>Range: %1 to %2 %3</source>
        <translation>Диапазон: от %1 до %2 %3</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingsDetails</name>
    <message>
        <location filename="../ui/settings/settings_details.cpp" line="+21"/>
        <source>Command / setting</source>
        <translation>Команда / настройка</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outcome</source>
        <translation>Результат</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Detail</source>
        <translation>Подробности</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Setting</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Profile</source>
        <translation>Профиль</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Help</source>
        <translation>Справка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outcomes</source>
        <translation>Результаты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Profile difference</source>
        <translation>Отличия профиля</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Range: %1 to %2 %3</source>
        <translation>Диапазон: от %1 до %2 %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Default: %1</source>
        <translation>По умолчанию: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Written with: %1</source>
        <translation>Записывается командой: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read back: %1</source>
        <translation>Чтение: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cannot be read back (write-only)</source>
        <translation>не читается (только запись)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>done</source>
        <translation>выполнено</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>problems</source>
        <translation>есть ошибки</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>receiver reports %1</source>
        <translation>приёмник сообщает %1</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingsToolbar</name>
    <message>
        <location filename="../ui/settings/settings_toolbar.cpp" line="+19"/>
        <source>Read</source>
        <translation>Прочитать</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read every setting the receiver reports</source>
        <translation>Прочитать все настройки, которые сообщает приёмник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Применить</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send the edited values (only what differs), then read them back</source>
        <translation>Отправить изменённые значения (только отличающиеся) и прочитать их обратно</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Revert</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the edits: show the receiver&apos;s values again</source>
        <translation>Отменить правки: снова показать значения приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to flash</source>
        <translation>Сохранить во флэш</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore defaults</source>
        <translation>Заводские настройки</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Presets</source>
        <translation>Предустановки</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Profile</source>
        <translation>Профиль</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Import and compare...</source>
        <translation>Импортировать и сравнить...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import settings profile</source>
        <translation>Импорт профиля настроек</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+5"/>
        <source>Settings profiles (*.json)</source>
        <translation>Профили настроек (*.json)</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Export...</source>
        <translation>Экспорт...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export settings profile</source>
        <translation>Экспорт профиля настроек</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Write the settings in force to the receiver&apos;s flash</source>
        <translation>Записать действующие настройки во флэш-память приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This receiver has no command to save its settings</source>
        <translation>У этого приёмника нет команды сохранения настроек</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingsView</name>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="+148"/>
        <source>%1 was not imported: %2</source>
        <translation>%1 не импортирован: %2</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location line="-40"/>
        <source>Find a setting</source>
        <translation>Найти настройку</translation>
    </message>
    <message>
        <location line="+187"/>
        <source>No setting matches &quot;%1&quot;.</source>
        <translation>Нет настроек, содержащих «%1».</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The %1 receiver has no settings this program knows.</source>
        <translation>У приёмника %1 нет настроек, известных программе.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect to a receiver: its settings appear here.</source>
        <translation>Подключите приёмник: здесь появятся его настройки.</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>From %1</source>
        <translation>Из %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Convert the %1 position to this form (WGS-84)</source>
        <translation>Пересчитать положение %1 в эту форму (WGS-84)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: select a setting to see its help.</source>
        <translation>%1: выберите настройку, чтобы увидеть справку.</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>receiver: %1</source>
        <translation>в приёмнике: %1</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Reading the receiver&apos;s settings...</source>
        <translation>Чтение настроек приёмника...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Nothing to apply: no value was changed.</source>
        <translation>Нечего применять: значения не изменены.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>Applying %n setting(s)...</source>
        <translation>
            <numerusform>Применяется %n настройка...</numerusform>
            <numerusform>Применяются %n настройки...</numerusform>
            <numerusform>Применяется %n настроек...</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Edits reverted.</source>
        <translation>Правки отменены.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>This receiver has no such command.</source>
        <translation>У этого приёмника нет такой команды.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 on the %2?

%3</source>
        <translation>%1 на приёмнике %2?

%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1...</source>
        <translation>%1...</translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>Preset &quot;%1&quot; loaded: %n setting(s) differ from the receiver. Apply sends them.</source>
        <translation>
            <numerusform>Предустановка «%1» загружена: %n настройка отличается от приёмника. «Применить» отправит её.</numerusform>
            <numerusform>Предустановка «%1» загружена: %n настройки отличаются от приёмника. «Применить» отправит их.</numerusform>
            <numerusform>Предустановка «%1» загружена: %n настроек отличаются от приёмника. «Применить» отправит их.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+43"/>
        <source>The receiver already has every setting of %1.</source>
        <translation>В приёмнике уже установлены все настройки из %1.</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n setting(s) of the profile differ from the receiver (model %1, firmware %2); they are loaded as edits: Apply sends them.</source>
        <translation>
            <numerusform>%n настройка профиля отличается от приёмника (модель %1, прошивка %2); она загружена как правка: «Применить» отправит её.</numerusform>
            <numerusform>%n настройки профиля отличаются от приёмника (модель %1, прошивка %2); они загружены как правки: «Применить» отправит их.</numerusform>
            <numerusform>%n настроек профиля отличаются от приёмника (модель %1, прошивка %2); они загружены как правки: «Применить» отправит их.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not connected to a receiver.</source>
        <translation>Нет подключения к приёмнику.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n setting(s) exported to %1.</source>
        <translation>
            <numerusform>%n настройка экспортирована в %1.</numerusform>
            <numerusform>%n настройки экспортированы в %1.</numerusform>
            <numerusform>%n настроек экспортировано в %1.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: cancelled.</source>
        <translation>%1: отменено.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing to send: the receiver already has these values.</source>
        <translation>Отправлять нечего: в приёмнике уже эти значения.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 command(s) failed, %3 setting(s) did not take; see Outcomes.</source>
        <translation>%1: команд с ошибкой: %2, не принятых настроек: %3; см. «Результаты».</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%1: done (%n command(s)).</source>
        <translation>
            <numerusform>%1: выполнено (%n команда).</numerusform>
            <numerusform>%1: выполнено (%n команды).</numerusform>
            <numerusform>%1: выполнено (%n команд).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The link was lost: these settings are read back when it returns.</source>
        <translation>Связь потеряна: эти настройки будут прочитаны, когда она вернётся.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1. Settings can be neither read nor changed from here.</source>
        <translation>%1. Отсюда настройки нельзя ни прочитать, ни изменить.</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SignalHistoryView</name>
    <message>
        <location filename="../ui/views/signal_history_view.cpp" line="+58"/>
        <source>No C/N0 yet</source>
        <translation>C/N0 ещё нет</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>−%1 min</source>
        <translation>−%1 мин</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>now</source>
        <translation>сейчас</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>end</source>
        <translation>конец</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>C/N0 (dB-Hz) of each signal</source>
        <translation>C/N0 (дБГц) каждого сигнала</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1/%2</source>
        <translation>%1/%2</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Highlight</source>
        <translation>Выделить</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>satellites, e.g. G05 R12 (or click a line)</source>
        <translation>спутники, например G05 R12 (или щёлкните линию)</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>last %n minute(s)</source>
        <translation>
            <numerusform>последняя %n минута</numerusform>
            <numerusform>последние %n минуты</numerusform>
            <numerusform>последние %n минут</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gnss::ui::SignalLevelsView</name>
    <message>
        <location filename="../ui/views/signal_levels_view.cpp" line="+140"/>
        <source>No satellites in view</source>
        <translation>Нет видимых спутников</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SkyPlotView</name>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="+111"/>
        <source>%1: SNR %2 dB-Hz%3</source>
        <translation>%1: С/Ш %2 дБГц%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, used</source>
        <translation>, в решении</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (%2)
elevation %3°, azimuth %4°</source>
        <translation>%1 (%2)
угол места %3°, азимут %4°</translation>
    </message>
    <message>
        <location line="+107"/>
        <source>N</source>
        <translation>С</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S</source>
        <translation>Ю</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E</source>
        <translation>В</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>W</source>
        <translation>З</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>Show tracks</source>
        <translation>Показывать треки</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show labels</source>
        <translation>Показывать подписи</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Constellations</source>
        <translation>Системы</translation>
    </message>
</context>
<context>
    <name>gnss::ui::TextEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="-56"/>
        <source>items separated by &apos;;&apos;</source>
        <translation>элементы через «;»</translation>
    </message>
</context>
<context>
    <name>gnss::ui::TimeSeriesModel</name>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="+37"/>
        <location line="+145"/>
        <source>Satellites used</source>
        <translation>Спутники в решении</translation>
    </message>
    <message>
        <location line="-143"/>
        <source>HDOP</source>
        <translation>HDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDOP</source>
        <translation>PDOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+143"/>
        <source>Fix type</source>
        <translation>Тип решения</translation>
    </message>
    <message>
        <location line="-135"/>
        <source>Std. dev. latitude</source>
        <translation>СКО широты</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Std. dev. longitude</source>
        <translation>СКО долготы</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Std. dev. height</source>
        <translation>СКО высоты</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baseline length</source>
        <translation>Длина базовой линии</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Altitude above sea level</source>
        <translation>Высота над уровнем моря</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>Mean SNR %1</source>
        <translation>Среднее С/Ш %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>DOP</source>
        <translation>DOP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mean SNR (dB-Hz)</source>
        <translation>Среднее С/Ш (дБГц)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Standard deviation (%1)</source>
        <translation>СКО (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baseline length (%1)</source>
        <translation>Длина базовой линии (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude above sea level (%1)</source>
        <translation>Высота над уровнем моря (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed (%1)</source>
        <translation>Скорость (%1)</translation>
    </message>
</context>
<context>
    <name>gnss::ui::TimelinePanel</name>
    <message>
        <location filename="../ui/logview/timeline_panel.cpp" line="+35"/>
        <source>Go to the start</source>
        <translation>В начало</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Previous event</source>
        <translation>Предыдущее событие</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Step back one epoch</source>
        <translation>На эпоху назад</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+123"/>
        <source>Play</source>
        <translation>Воспроизвести</translation>
    </message>
    <message>
        <location line="-119"/>
        <source>Step forward one epoch</source>
        <translation>На эпоху вперёд</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Next event</source>
        <translation>Следующее событие</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Go to the end</source>
        <translation>В конец</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Playing speed (Ctrl+Up faster, Ctrl+Down slower)</source>
        <translation>Скорость воспроизведения (Ctrl+Вверх — быстрее, Ctrl+Вниз — медленнее)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>as fast as possible</source>
        <translation>как можно быстрее</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Faster</source>
        <translation>Быстрее</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Slower</source>
        <translation>Медленнее</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Go to: 10:42:00, #1200</source>
        <translation>Перейти: 10:42:00, #1200</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A time of day (10:42:00), a UTC time (2024-03-15T10:42:00Z) or an epoch number (#1200), then Enter (Ctrl+G)</source>
        <translation>Время суток (10:42:00), время UTC (2024-03-15T10:42:00Z) или номер эпохи (#1200), затем Enter (Ctrl+G)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Go to a time…</source>
        <translation>Перейти ко времени…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Range start</source>
        <translation>Начало интервала</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Range end</source>
        <translation>Конец интервала</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Whole log</source>
        <translation>Весь журнал</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Follow</source>
        <translation>Следить</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep reading a log that is still being written; the cursor stays at its end</source>
        <translation>Дочитывать журнал, который ещё пишется; курсор остаётся в его конце</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+150"/>
        <source>Stop indexing this log (Esc)</source>
        <translation>Остановить индексацию журнала (Esc)</translation>
    </message>
    <message>
        <location line="-126"/>
        <source>Click or drag to move; Shift+drag selects a range</source>
        <translation>Щелчок или перетаскивание — переход; Shift+перетаскивание — выбор интервала</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>no later event</source>
        <translation>дальше событий нет</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no earlier event</source>
        <translation>раньше событий нет</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not a time: write 10:42:00, 2024-03-15T10:42:00Z or #1200</source>
        <translation>это не время: напишите 10:42:00, 2024-03-15T10:42:00Z или #1200</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 is before the log&apos;s start: it runs from %2 to %3</source>
        <translation>%1 — раньше начала журнала: он идёт с %2 по %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the log has no epochs</source>
        <translation>в журнале нет эпох</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is after the log&apos;s end: it runs from %2 to %3</source>
        <translation>%1 — позже конца журнала: он идёт с %2 по %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the log&apos;s epochs carry no time for %1: write an epoch number (#1200)</source>
        <translation>у эпох журнала нет времени для %1: укажите номер эпохи (#1200)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Stop indexing: %1 (Esc)</source>
        <translation>Остановить индексацию: %1 (Esc)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>#%1 / %2</source>
        <translation>№%1 / %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · %1 · %2</source>
        <translation> · %1 · %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> · range #%1–#%2</source>
        <translation> · интервал №%1–№%2</translation>
    </message>
</context>
<context>
    <name>gnss::ui::TimelineStrip</name>
    <message>
        <location filename="../ui/logview/timeline_strip.cpp" line="+144"/>
        <source>Open a log (File → Open Log…)</source>
        <translation>Откройте журнал (Файл → Открыть журнал…)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>#%1 · %2 · %3</source>
        <translation>№%1 · %2 · %3</translation>
    </message>
</context>
</TS>
