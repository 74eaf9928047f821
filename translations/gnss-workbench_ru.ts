<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru" sourcelanguage="en">
<context>
    <name>FixType</name>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="+37"/>
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
        <location filename="../ui/views/value_format.cpp" line="+45"/>
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
    <name>QObject</name>
    <message>
        <location filename="../app/cli/cmd_config.cpp" line="+113"/>
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
        <location line="+33"/>
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
        <location line="+12"/>
        <source>unknown setting &apos;%1&apos; (gnss-cli schema %2 lists them)</source>
        <translation>неизвестная настройка «%1» (список настроек выводит gnss-cli schema %2)</translation>
    </message>
    <message>
        <location line="+47"/>
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
        <location line="+27"/>
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
    <message>
        <location filename="../protocol/config/settings_profile.cpp" line="+46"/>
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
        <location line="+11"/>
        <source>the profile is for dialect &apos;%1&apos;, the receiver speaks &apos;%2&apos;</source>
        <translation>профиль предназначен для диалекта «%1», а приёмник использует «%2»</translation>
    </message>
    <message>
        <location line="+6"/>
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
        <location line="+10"/>
        <source>cannot write %1: %2</source>
        <translation>не удаётся записать %1: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cannot read %1: %2</source>
        <translation>не удаётся прочитать %1: %2</translation>
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
        <source>gpsd %1</source>
        <translation>gpsd %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No source</source>
        <translation>Нет источника</translation>
    </message>
</context>
<context>
    <name>StartupOptions</name>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="+14"/>
        <source>Configure and monitor GNSS receivers.</source>
        <translation>Настройка и мониторинг приёмников ГНСС.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exit status: 0 closed normally, 1 the --screenshot could not be saved, 2 usage error.</source>
        <translation>Код завершения: 0 — обычное закрытие, 1 — не удалось сохранить --screenshot, 2 — ошибка в параметрах запуска.</translation>
    </message>
    <message>
        <location line="+6"/>
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
        <source>Show this dock in front of its tab group: settings, console, sky, signal, fix, satellites, rtk, charts, corrections, deviation, attitude, stats, info.</source>
        <translation>Показать эту панель поверх её группы вкладок: settings, console, sky, signal, fix, satellites, rtk, charts, corrections, deviation, attitude, stats, info.</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>Invalid --gpsd: %1</source>
        <translation>Неверное значение --gpsd: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Give one source at most: --port, --tcp, --gpsd, --replay or --sim.</source>
        <translation>Укажите не более одного источника: --port, --tcp, --gpsd, --replay или --sim.</translation>
    </message>
    <message>
        <location line="-66"/>
        <source>Save an image of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Quit after this many seconds.</source>
        <translation>Выйти через указанное число секунд.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Unexpected argument &apos;%1&apos;</source>
        <translation>Лишний аргумент «%1»</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Invalid baud rate: %1</source>
        <translation>Неверная скорость порта: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Invalid --quit-after: %1</source>
        <translation>Неверное значение --quit-after: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Unknown simulated receiver &apos;%1&apos; (use %2)</source>
        <translation>Неизвестный имитатор приёмника «%1» (допустимо: %2)</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="+67"/>
        <source>Unknown dock &apos;%1&apos; (use %2)</source>
        <translation>Неизвестная панель «%1» (допустимо: %2)</translation>
    </message>
</context>
<context>
    <name>gnss::app::ConnectionBar</name>
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
        <location line="+105"/>
        <source>Connect</source>
        <translation>Подключить</translation>
    </message>
    <message>
        <location line="-91"/>
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
    <name>gnss::app::ConnectionController</name>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="+23"/>
        <location line="+140"/>
        <source>Not connected</source>
        <translation>Нет подключения</translation>
    </message>
    <message>
        <location line="-107"/>
        <source>No source chosen</source>
        <translation>Источник не выбран</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+23"/>
        <source>Cannot open %1: %2</source>
        <translation>Не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Connected: %1</source>
        <translation>Подключено: %1</translation>
    </message>
    <message>
        <location line="-77"/>
        <location line="+62"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-104"/>
        <source>%1: detecting the baud rate: trying %2…</source>
        <translation>%1: определение скорости: проверяется %2…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: detecting the baud rate: %2; trying %3…</source>
        <translation>%1: определение скорости: %2; проверяется %3…</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1: detecting the baud rate…</source>
        <translation>%1: определение скорости…</translation>
    </message>
    <message>
        <location line="+129"/>
        <source>%1 cannot take commands</source>
        <translation>%1 не принимает команды</translation>
    </message>
    <message>
        <location line="-118"/>
        <source>Baud rate not found: %1</source>
        <translation>Скорость не найдена: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baud rate detected: %1</source>
        <translation>Скорость определена: %1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 — trying again in %2 s</source>
        <translation>%1 — повтор через %2 с</translation>
    </message>
    <message>
        <location line="+4"/>
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
        <location line="-46"/>
        <source>Opening %1…</source>
        <translation>Открытие %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting to %1…</source>
        <translation>Подключение к %1…</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Connected: %1 (detected)</source>
        <translation>Подключено: %1 (определено)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Not connected: nothing was sent</source>
        <translation>Нет подключения: ничего не отправлено</translation>
    </message>
</context>
<context>
    <name>gnss::app::CorrectionsController</name>
    <message>
        <location filename="../app/gui/corrections_controller.cpp" line="+40"/>
        <source>The password was not read from the keychain: %1</source>
        <translation>Пароль не прочитан из связки ключей: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The password was not kept in the keychain: %1</source>
        <translation>Пароль не сохранён в связке ключей: %1</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Not started</source>
        <translation>Не запущено</translation>
    </message>
</context>
<context>
    <name>gnss::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+51"/>
        <source>GNSS Workbench</source>
        <translation>GNSS Workbench</translation>
    </message>
    <message>
        <location line="+236"/>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open Log...</source>
        <translation>&amp;Открыть журнал...</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Receiver</source>
        <translation>&amp;Приёмник</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Connect</source>
        <translation>&amp;Подключить</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Отключить</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About GNSS Workbench</source>
        <translation>&amp;О программе GNSS Workbench</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>About &amp;Qt</source>
        <translation>О &amp;Qt</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Open Log</source>
        <translation>Открыть журнал</translation>
    </message>
    <message>
        <location line="-210"/>
        <source>trying %1…</source>
        <translation>проверка %1…</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location line="+75"/>
        <source>Sky plot</source>
        <translation>Небосвод</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fix and position</source>
        <translation>Решение и координаты</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fix</source>
        <translation>Решение</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+1"/>
        <source>Signal levels</source>
        <translation>Уровни сигналов</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Satellites</source>
        <translation>Спутники</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location line="+1"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Receiver information</source>
        <translation>Сведения о приёмнике</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RTK</source>
        <translation>RTK</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Charts</source>
        <translation>Графики</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+1"/>
        <source>Deviation</source>
        <translation>Разброс</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attitude</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude and time marks</source>
        <translation>Ориентация и метки времени</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Corrections</source>
        <translation>Поправки</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Corrections (RTCM)</source>
        <translation>Поправки (RTCM)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Settings</source>
        <translation>Настройки</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Receiver settings</source>
        <translation>Настройки приёмника</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Not sent: %1</source>
        <translation>Не отправлено: %1</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>NMEA logs (*.nmea *.log *.txt);;All files (*)</source>
        <translation>Журналы NMEA (*.nmea *.log *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Record...</source>
        <translation>&amp;Запись...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Sky plot &amp;tracks</source>
        <translation>&amp;Треки на небосводе</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location line="+13"/>
        <source>About GNSS Workbench</source>
        <translation>О программе GNSS Workbench</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Configure and monitor NVS NV08C-RTK, GeoStar GeoS-5, Nemerix and NMEA-0183 receivers.</source>
        <translation>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Настройка и мониторинг приёмников NVS NV08C-RTK, GeoStar GeoS-5, Nemerix и NMEA-0183.</translation>
    </message>
    <message>
        <location line="+38"/>
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
        <location line="+3"/>
        <source>%1 B/s · %2 sentences/s</source>
        <translation>%1 Б/с · %2 предл./с</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>checksum errors: %1</source>
        <translation>ошибок контрольной суммы: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>● REC</source>
        <translation>● ЗАПИСЬ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No fix</source>
        <translation>Нет решения</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Record to</source>
        <translation>Записывать в</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMEA logs (*.nmea)</source>
        <translation>Журналы NMEA (*.nmea)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Record</source>
        <translation>Запись</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot record to %1: connect to a receiver first, and check the folder is writable.</source>
        <translation>Не удаётся записывать в %1: сначала подключитесь к приёмнику и проверьте, что папка доступна для записи.</translation>
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
    <name>gnss::config::SettingsEngine</name>
    <message>
        <location filename="../protocol/config/settings_engine.cpp" line="+31"/>
        <source>verified</source>
        <translation>проверено</translation>
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
        <location line="+37"/>
        <source>the link changed during the operation</source>
        <translation>подключение сменилось во время операции</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 cannot take commands</source>
        <translation>%1 не принимает команды</translation>
    </message>
    <message>
        <location line="+29"/>
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
        <location line="+64"/>
        <source>Read settings</source>
        <translation>Чтение настроек</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+70"/>
        <source>unknown setting &apos;%1&apos; of the %2 dialect</source>
        <translation>неизвестная настройка «%1» диалекта %2</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Apply settings</source>
        <translation>Применение настроек</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 cannot be set</source>
        <translation>%1 нельзя задать</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the %1 dialect has no settings encoder</source>
        <translation>у диалекта %1 нет кодировщика настроек</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>nothing was sent: %1</source>
        <translation>ничего не отправлено: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Action</source>
        <translation>Действие</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the %1 receiver has no &apos;%2&apos; command</source>
        <translation>у приёмника %1 нет команды «%2»</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>could not read back: %1</source>
        <translation>не удалось прочитать обратно: %1</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Apply profile</source>
        <translation>Применение профиля</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the profile is for dialect &apos;%1&apos;, the receiver speaks &apos;%2&apos;</source>
        <translation>профиль предназначен для диалекта «%1», а приёмник использует «%2»</translation>
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
        <location line="+28"/>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>%1; trying again in %2 s</source>
        <translation>%1; повтор через %2 с</translation>
    </message>
    <message>
        <location line="+18"/>
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
        <location filename="../protocol/corrections/ntrip_source.cpp" line="+71"/>
        <source>No mountpoint given for %1: pick one from its source table</source>
        <translation>Не указана точка подключения для %1: выберите её из таблицы источников</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connecting to %1</source>
        <translation>Подключение к %1</translation>
    </message>
    <message>
        <location line="+25"/>
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
        <location line="+5"/>
        <source>%1 refused the user name or password for mountpoint %2 (401 Unauthorized, %3 reply)</source>
        <translation>%1: имя пользователя или пароль для точки подключения %2 не приняты (401 Unauthorized, ответ %3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mountpoint %1 not found on %2 (404 Not Found, %3 reply)</source>
        <translation>Точка подключения %1 не найдена на %2 (404 Not Found, ответ %3)</translation>
    </message>
    <message>
        <location line="+4"/>
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
    <name>gnss::corrections::SerialCorrectionSource</name>
    <message>
        <location filename="../protocol/corrections/serial_correction_source.cpp" line="+11"/>
        <source>Receiving RTCM from %1</source>
        <translation>Приём RTCM от %1</translation>
    </message>
    <message>
        <location line="+8"/>
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
        <location filename="../protocol/corrections/source_table_request.cpp" line="+11"/>
        <source>No source table from %1 within %2 s</source>
        <translation>Таблица источников от %1 не получена за %2 с</translation>
    </message>
    <message>
        <location line="+14"/>
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
        <location filename="../protocol/corrections/tcp_correction_source.cpp" line="+9"/>
        <source>Connected to %1, waiting for RTCM</source>
        <translation>Подключено к %1, ожидание RTCM</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Receiving RTCM from %1</source>
        <translation>Приём RTCM от %1</translation>
    </message>
    <message>
        <location line="+6"/>
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
        <location filename="../protocol/link/recording.cpp" line="+25"/>
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
        <location line="+28"/>
        <source>%1, line %2: %3</source>
        <translation>%1, строка %2: %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not an index line</source>
        <translation>это не строка индекса</translation>
    </message>
    <message>
        <location line="+5"/>
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
        <location line="+16"/>
        <source>Baud detection cancelled</source>
        <translation>Определение скорости отменено</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>No data at any rate (tried %1 baud): check the cable, the port and that the receiver is powered</source>
        <translation>Нет данных ни на одной скорости (проверено: %1 бод): проверьте кабель, порт и питание приёмника</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Data but never a valid sentence at %1 baud: wrong framing (data bits, parity, stop bits) or the receiver is not sending NMEA?</source>
        <translation>Данные есть, но ни одного корректного сообщения на скоростях %1 бод: неверный формат кадра (биты данных, чётность, стоповые биты) или приёмник не передаёт NMEA?</translation>
    </message>
</context>
<context>
    <name>gnss::link::CommandQueue</name>
    <message>
        <location filename="../protocol/link/command_queue.cpp" line="+47"/>
        <location line="+199"/>
        <source>accepted</source>
        <translation>принято</translation>
    </message>
    <message>
        <location line="-196"/>
        <source>refused</source>
        <translation>отклонено</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>timed out</source>
        <translation>тайм-аут</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>link lost</source>
        <translation>связь потеряна</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancelled</source>
        <translation>отменено</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sent</source>
        <translation>отправлено</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>failed</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Not a sentence: %1 (%2)</source>
        <translation>Некорректное сообщение: %1 (%2)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cancelled before the receiver answered</source>
        <translation>отменено до ответа приёмника</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cancelled before it was sent</source>
        <translation>отменено до отправки</translation>
    </message>
    <message>
        <location line="+51"/>
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
    <name>gnss::link::GpsdTransport</name>
    <message>
        <location filename="../protocol/link/gpsd_transport.cpp" line="+29"/>
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
        <location line="+39"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Не удаётся подключиться к %1: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>this is not gpsd: it did not greet with its VERSION</source>
        <translation>это не gpsd: нет приветствия VERSION</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>gpsd has no device %1 (it has none)</source>
        <translation>у gpsd нет устройства %1 (устройств нет вовсе)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gpsd has no device %1 (it has %2)</source>
        <translation>у gpsd нет устройства %1 (есть: %2)</translation>
    </message>
    <message>
        <location line="+17"/>
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
        <location line="+82"/>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <location line="-46"/>
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
        <location filename="../protocol/link/replay_transport.cpp" line="+80"/>
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
        <location line="+18"/>
        <source>%1 has no timestamp index (%2): replay it with sentence times instead</source>
        <translation>У %1 нет индекса времени (%2): воспроизводите его по времени в сообщениях</translation>
    </message>
    <message>
        <location line="+45"/>
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
        <location line="+17"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>gnss::link::SimulatorTransport</name>
    <message>
        <location filename="../app/common/simulator_transport.cpp" line="+23"/>
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
        <location filename="../protocol/link/tcp_transport.cpp" line="+16"/>
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
        <location line="+24"/>
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
    <name>gnss::ui::AttitudeView</name>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="+42"/>
        <source>Attitude</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <source>Time (UTC)</source>
        <translation>Время (UTC)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Acceleration</source>
        <translation>Ускорение</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location line="+7"/>
        <source>Counter</source>
        <translation>Счётчик</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>GPS time of week (s)</source>
        <translation>Время недели GPS (с)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Altitude MSL (m)</source>
        <translation>Высота над уровнем моря (м)</translation>
    </message>
    <message>
        <location line="+36"/>
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
    <name>gnss::ui::ChartsView</name>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="+108"/>
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
        <location line="+184"/>
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
    <name>gnss::ui::ConsoleView</name>
    <message>
        <location filename="../ui/views/console_view.cpp" line="+32"/>
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
        <location line="+50"/>
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
        <location line="+23"/>
        <source>Not sent: %1</source>
        <translation>Не отправлено: %1</translation>
    </message>
</context>
<context>
    <name>gnss::ui::CoordinateEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="+265"/>
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
        <location filename="../ui/views/corrections_view.cpp" line="+55"/>
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
        <location line="+141"/>
        <source>Start</source>
        <translation>Запустить</translation>
    </message>
    <message>
        <location line="-137"/>
        <source>Not started</source>
        <translation>Не запущено</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Received</source>
        <translation>Принято</translation>
    </message>
    <message>
        <location line="+8"/>
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
        <location line="+12"/>
        <source>Correction age, s (last 10 min)</source>
        <translation>Возраст поправок, с (последние 10 мин)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>kept in the keychain</source>
        <translation>хранится в связке ключей</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Give the host of the corrections.</source>
        <translation>Укажите хост источника поправок.</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location line="+2"/>
        <source>%1, %2, %3 m</source>
        <translation>%1, %2, %3 м</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ECEF %1, %2, %3 m</source>
        <translation>ECEF %1, %2, %3 м</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Base station %1 (%2): %3; distance to the rover %4</source>
        <translation>Базовая станция %1 (%2): %3; расстояние до ровера %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 km</source>
        <translation>%1 км</translation>
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
        <location line="+39"/>
        <source>East (m)</source>
        <translation>Восток (м)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>North (m)</source>
        <translation>Север (м)</translation>
    </message>
    <message>
        <location line="+35"/>
        <location line="+108"/>
        <source>CEP50</source>
        <translation>CEP50</translation>
    </message>
    <message>
        <location line="-107"/>
        <location line="+108"/>
        <source>CEP95</source>
        <translation>CEP95</translation>
    </message>
    <message>
        <location line="-107"/>
        <location line="+108"/>
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
        <location line="+94"/>
        <source>Reference not used: type degrees such as 55.75123456 N and 37.61812345 E (or signed, -33.9 for south). Centred on the mean.</source>
        <translation>Опорная точка не используется: введите градусы, например 55.75123456 N и 37.61812345 E (или со знаком: -33.9 для южной широты). Центр — по среднему положению.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>reference %1, %2</source>
        <translation>опорная точка %1, %2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mean %1, %2</source>
        <translation>среднее %1, %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 east, %2 north</source>
        <translation>%1 на восток, %2 на север</translation>
    </message>
</context>
<context>
    <name>gnss::ui::FixView</name>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="+30"/>
        <source>Degrees</source>
        <translation>Градусы</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deg min sec</source>
        <translation>Град. мин. сек.</translation>
    </message>
    <message>
        <location line="+8"/>
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
        <source>UTC</source>
        <translation>UTC</translation>
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
        <location line="+37"/>
        <source>No data</source>
        <translation>Нет данных</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+1"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 m/s  (%2 km/h)</source>
        <translation>%1 м/с  (%2 км/ч)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>s</source>
        <translation>с</translation>
    </message>
</context>
<context>
    <name>gnss::ui::MessageStatsModel</name>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="+57"/>
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
    <name>gnss::ui::ReceiverInfoView</name>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="+48"/>
        <source>Item</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <location line="+50"/>
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
    <name>gnss::ui::RtkView</name>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="+46"/>
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
        <location line="+7"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Correction age</source>
        <translation>Возраст поправок</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance to base</source>
        <translation>Расстояние до базы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base station id</source>
        <translation>Номер базовой станции</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTCM messages</source>
        <translation>Сообщения RTCM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTCM good</source>
        <translation>RTCM без ошибок</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTCM errors</source>
        <translation>Ошибки RTCM</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Baseline base → rover</source>
        <translation>Базовая линия база → ровер</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+12"/>
        <source>North</source>
        <translation>Север</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+12"/>
        <source>East</source>
        <translation>Восток</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+12"/>
        <source>Vertical</source>
        <translation>Вертикаль</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+8"/>
        <source>Length</source>
        <translation>Длина</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Course</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+5"/>
        <source>Pitch</source>
        <translation>Тангаж</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Heading (antenna baseline)</source>
        <translation>Курс (линия антенн)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+15"/>
        <source>Heading</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location line="-7"/>
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
        <location line="+1"/>
        <source>Velocity east</source>
        <translation>Скорость на восток</translation>
    </message>
    <message>
        <location line="+1"/>
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
        <location line="+59"/>
        <source>Autonomous</source>
        <translation>Автономный</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential</source>
        <translation>Дифференциальный</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>m/s</source>
        <translation>м/с</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location line="+46"/>
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
    <name>gnss::ui::SettingEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="-40"/>
        <source>Range: %1 to %2 %3</source>
        <translation>Диапазон: от %1 до %2 %3</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingsView</name>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="+66"/>
        <source>Read</source>
        <translation>Прочитать</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read every setting the receiver reports</source>
        <translation>Прочитать все настройки, которые сообщает приёмник</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Применить</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send the edited values (only what differs), then read them back</source>
        <translation>Отправить изменённые значения (только отличающиеся) и прочитать их обратно</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Revert</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <location line="+1"/>
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
        <location line="+2"/>
        <source>Reset</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Presets</source>
        <translation>Предустановки</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+69"/>
        <source>Profile</source>
        <translation>Профиль</translation>
    </message>
    <message>
        <location line="-66"/>
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
        <location line="+6"/>
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
        <location line="+6"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Find a setting</source>
        <translation>Найти настройку</translation>
    </message>
    <message>
        <location line="+25"/>
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
        <location line="+154"/>
        <source>No setting matches &quot;%1&quot;.</source>
        <translation>Нет настроек, содержащих «%1».</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The %1 receiver has no settings this program knows.</source>
        <translation>У приёмника %1 нет настроек, известных программе.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect to a receiver: its settings appear here.</source>
        <translation>Подключите приёмник: здесь появятся его настройки.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>From %1</source>
        <translation>Из %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Convert the %1 position to this form (WGS-84)</source>
        <translation>Пересчитать положение %1 в эту форму (WGS-84)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: select a setting to see its help.</source>
        <translation>%1: выберите настройку, чтобы увидеть справку.</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>receiver: %1</source>
        <translation>в приёмнике: %1</translation>
    </message>
    <message>
        <location line="+43"/>
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
        <location line="+28"/>
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
        <location line="+3"/>
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
        <location line="+27"/>
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
        <location line="+7"/>
        <source>done</source>
        <translation>выполнено</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>problems</source>
        <translation>есть ошибки</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>receiver reports %1</source>
        <translation>приёмник сообщает %1</translation>
    </message>
    <message>
        <location line="+11"/>
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
        <location line="+18"/>
        <source>Write the settings in force to the receiver&apos;s flash</source>
        <translation>Записать действующие настройки во флэш-память приёмника</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This receiver has no command to save its settings</source>
        <translation>У этого приёмника нет команды сохранения настроек</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1. Settings can be neither read nor changed from here.</source>
        <translation>%1. Отсюда настройки нельзя ни прочитать, ни изменить.</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SignalLevelsView</name>
    <message>
        <location filename="../ui/views/signal_levels_view.cpp" line="+119"/>
        <source>No satellites in view</source>
        <translation>Нет видимых спутников</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SkyPlotView</name>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="+110"/>
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
        <location line="+123"/>
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
        <location line="+103"/>
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
        <location filename="../ui/settings/setting_editors.cpp" line="-46"/>
        <source>items separated by &apos;;&apos;</source>
        <translation>элементы через «;»</translation>
    </message>
</context>
<context>
    <name>gnss::ui::TimeSeriesModel</name>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="+145"/>
        <location line="+36"/>
        <source>Satellites used</source>
        <translation>Спутники в решении</translation>
    </message>
    <message>
        <location line="-35"/>
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
        <location line="+35"/>
        <source>Fix type</source>
        <translation>Тип решения</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>Std. dev. latitude</source>
        <translation>СКО широты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Std. dev. longitude</source>
        <translation>СКО долготы</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Std. dev. height</source>
        <translation>СКО высоты</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baseline length</source>
        <translation>Длина базовой линии</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude above sea level</source>
        <translation>Высота над уровнем моря</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Mean SNR %1</source>
        <translation>Среднее С/Ш %1</translation>
    </message>
    <message>
        <location line="+24"/>
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
        <source>Standard deviation (m)</source>
        <translation>СКО (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baseline length (m)</source>
        <translation>Длина базовой линии (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude above sea level (m)</source>
        <translation>Высота над уровнем моря (м)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed (m/s)</source>
        <translation>Скорость (м/с)</translation>
    </message>
</context>
</TS>
