<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru" sourcelanguage="en">
<context>
    <name>FixType</name>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="37"/>
        <source>No fix</source>
        <translation>Нет решения</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="38"/>
        <source>Estimated</source>
        <translation>Счисление</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="39"/>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="40"/>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="41"/>
        <source>DGNSS</source>
        <translation>DGNSS</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="42"/>
        <source>RTK float</source>
        <translation>RTK float</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="43"/>
        <source>RTK fixed</source>
        <translation>RTK fixed</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="44"/>
        <source>Fixed position</source>
        <translation>Фиксированные координаты</translation>
    </message>
    <message>
        <location filename="../ui/style/gnss_style.cpp" line="45"/>
        <source>Simulator</source>
        <translation>Симулятор</translation>
    </message>
</context>
<context>
    <name>Hemisphere</name>
    <message>
        <location filename="../ui/views/value_format.cpp" line="39"/>
        <source>N</source>
        <translation>с. ш.</translation>
    </message>
    <message>
        <location filename="../ui/views/value_format.cpp" line="39"/>
        <source>S</source>
        <translation>ю. ш.</translation>
    </message>
    <message>
        <location filename="../ui/views/value_format.cpp" line="43"/>
        <source>E</source>
        <translation>в. д.</translation>
    </message>
    <message>
        <location filename="../ui/views/value_format.cpp" line="43"/>
        <source>W</source>
        <translation>з. д.</translation>
    </message>
</context>
<context>
    <name>StartupOptions</name>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="10"/>
        <source>Configure and monitor GNSS receivers.</source>
        <translation>Настройка и мониторинг приёмников ГНСС.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="15"/>
        <source>Serial port.</source>
        <translation>Последовательный порт.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="18"/>
        <source>Baud rate (default: auto).</source>
        <translation>Скорость порта (по умолчанию: автоопределение).</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="22"/>
        <source>TCP source HOST:PORT.</source>
        <translation>Источник TCP ХОСТ:ПОРТ.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="26"/>
        <source>Replay a recorded log.</source>
        <translation>Воспроизвести записанный журнал.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="30"/>
        <source>Built-in simulated receiver: nvs, geostar, nemerix, nmea.</source>
        <translation>Встроенный имитатор приёмника: nvs, geostar, nemerix, nmea.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="35"/>
        <source>Save an image of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="39"/>
        <source>Quit after this many seconds.</source>
        <translation>Выйти через указанное число секунд.</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="60"/>
        <source>Invalid baud rate: %1</source>
        <translation>Неверная скорость порта: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="69"/>
        <source>Invalid --quit-after: %1</source>
        <translation>Неверное значение --quit-after: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="76"/>
        <source>Unknown simulated receiver &apos;%1&apos; (use %2)</source>
        <translation>Неизвестный имитатор приёмника «%1» (допустимо: %2)</translation>
    </message>
    <message>
        <location filename="../app/gui/startup_options.cpp" line="84"/>
        <source>Give one source at most: --port, --tcp, --replay or --sim.</source>
        <translation>Укажите не более одного источника: --port, --tcp, --replay или --sim.</translation>
    </message>
</context>
<context>
    <name>gnss::app::ConnectionBar</name>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="18"/>
        <source>Connection</source>
        <translation>Подключение</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="20"/>
        <source>Source </source>
        <translation>Источник </translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="26"/>
        <source>  Baud </source>
        <translation>  Скорость </translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="29"/>
        <source>auto</source>
        <translation>авто</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="32"/>
        <location filename="../app/gui/connection_bar.cpp" line="118"/>
        <source>Connect</source>
        <translation>Подключить</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="45"/>
        <source>TCP source</source>
        <translation>Источник TCP</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="45"/>
        <source>Host and port (HOST:PORT):</source>
        <translation>Хост и порт (ХОСТ:ПОРТ):</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="50"/>
        <source>Open Log</source>
        <translation type="unfinished">Открыть журнал</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="51"/>
        <source>NMEA logs (*.nmea *.log *.txt);;All files (*)</source>
        <translation type="unfinished">Журналы NMEA (*.nmea *.log *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="71"/>
        <source>%1
Manufacturer: %2
Serial number: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="79"/>
        <source>Simulated NVS NV08C-RTK</source>
        <translation>Имитатор NVS NV08C-RTK</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="80"/>
        <source>Simulated GeoStar GeoS-5</source>
        <translation>Имитатор GeoStar GeoS-5</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="81"/>
        <source>Simulated Nemerix VT002</source>
        <translation>Имитатор Nemerix VT002</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="82"/>
        <source>Simulated NMEA receiver</source>
        <translation>Имитатор приёмника NMEA</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="86"/>
        <source>TCP…</source>
        <translation>TCP…</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="87"/>
        <source>Open log…</source>
        <translation>Открыть журнал…</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_bar.cpp" line="118"/>
        <source>Disconnect</source>
        <translation>Отключить</translation>
    </message>
</context>
<context>
    <name>gnss::app::ConnectionController</name>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="17"/>
        <location filename="../app/gui/connection_controller.cpp" line="124"/>
        <source>Not connected</source>
        <translation type="unfinished">Нет подключения</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="32"/>
        <source>No source chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="39"/>
        <location filename="../app/gui/connection_controller.cpp" line="107"/>
        <source>Cannot open %1: %2</source>
        <translation>Не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="46"/>
        <source>Detecting baud rate: trying %1…</source>
        <translation>Определение скорости: пробуем %1…</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="48"/>
        <source>Detecting baud rate…</source>
        <translation>Определение скорости…</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="75"/>
        <source>TCP source must be HOST:PORT, got &apos;%1&apos;</source>
        <translation>Источник TCP задаётся как ХОСТ:ПОРТ, получено «%1»</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="94"/>
        <source>Link lost: %1 — retrying every second</source>
        <translation>Связь потеряна: %1 — повтор каждую секунду</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="96"/>
        <location filename="../app/gui/connection_controller.cpp" line="110"/>
        <source>Connected: %1</source>
        <translation>Подключено: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="104"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_controller.cpp" line="129"/>
        <source>Not connected: nothing was sent</source>
        <translation>Нет подключения: ничего не отправлено</translation>
    </message>
</context>
<context>
    <name>gnss::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="46"/>
        <source>GNSS Workbench</source>
        <translation>GNSS Workbench</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="170"/>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="171"/>
        <source>&amp;Open Log...</source>
        <translation>&amp;Открыть журнал...</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="186"/>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="189"/>
        <source>&amp;Receiver</source>
        <translation>&amp;Приёмник</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="191"/>
        <source>&amp;Connect</source>
        <translation>&amp;Подключить</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="192"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="193"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Отключить</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="194"/>
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="196"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="216"/>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="217"/>
        <source>&amp;About GNSS Workbench</source>
        <translation>&amp;О программе GNSS Workbench</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="223"/>
        <source>About &amp;Qt</source>
        <translation>О &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="172"/>
        <source>Open Log</source>
        <translation>Открыть журнал</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="66"/>
        <source>Command: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="106"/>
        <source>Sky plot</source>
        <translation>Небосвод</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="107"/>
        <source>Fix and position</source>
        <translation>Решение и координаты</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="108"/>
        <source>Signal levels</source>
        <translation>Уровни сигналов</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="115"/>
        <source>Satellites</source>
        <translation>Спутники</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="117"/>
        <source>Console</source>
        <translation>Консоль</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="118"/>
        <source>Message statistics</source>
        <translation>Статистика сообщений</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="120"/>
        <source>Receiver information</source>
        <translation>Сведения о приёмнике</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="123"/>
        <source>RTK</source>
        <translation>RTK</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="125"/>
        <source>Charts</source>
        <translation>Графики</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="127"/>
        <source>Deviation</source>
        <translation>Разброс</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="129"/>
        <source>Attitude and time marks</source>
        <translation>Ориентация и метки времени</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="139"/>
        <source>Receiver settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="151"/>
        <source>Not sent: %1</source>
        <translation>Не отправлено: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="173"/>
        <source>NMEA logs (*.nmea *.log *.txt);;All files (*)</source>
        <translation>Журналы NMEA (*.nmea *.log *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="181"/>
        <source>&amp;Record...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="183"/>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="200"/>
        <source>Sky plot &amp;tracks</source>
        <translation>&amp;Треки на небосводе</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="203"/>
        <source>&amp;Reset layout</source>
        <translation>&amp;Сбросить расположение</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="204"/>
        <source>T&amp;heme</source>
        <translation>&amp;Оформление</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="206"/>
        <source>Follow the system</source>
        <translation>Как в системе</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="207"/>
        <source>Light</source>
        <translation>Светлое</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="207"/>
        <source>Dark</source>
        <translation>Тёмное</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="218"/>
        <source>About GNSS Workbench</source>
        <translation>О программе GNSS Workbench</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="219"/>
        <source>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Configure and monitor NVS NV08C-RTK, GeoStar GeoS-5, Nemerix and NMEA-0183 receivers.</source>
        <translation>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Настройка и мониторинг приёмников NVS NV08C-RTK, GeoStar GeoS-5, Nemerix и NMEA-0183.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250"/>
        <source>dialect: —</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="252"/>
        <source> (firmware %1)</source>
        <translation> (прошивка %1)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="255"/>
        <source>%1 B/s · %2 sentences/s</source>
        <translation>%1 Б/с · %2 предл./с</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="256"/>
        <source>checksum errors: %1</source>
        <translation>ошибок контрольной суммы: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="259"/>
        <source>● REC</source>
        <translation>● ЗАПИСЬ</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="263"/>
        <source>No fix</source>
        <translation type="unfinished">Нет решения</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="274"/>
        <source>Record to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="275"/>
        <source>NMEA logs (*.nmea)</source>
        <translation>Журналы NMEA (*.nmea)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="278"/>
        <source>Record</source>
        <translation>Запись</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="278"/>
        <source>Cannot record to %1: connect to a receiver first, and check the folder is writable.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::app::SourceSpec</name>
    <message>
        <location filename="../app/gui/source_spec.cpp" line="45"/>
        <source>%1 at %2 baud</source>
        <translation>%1 на %2 бод</translation>
    </message>
    <message>
        <location filename="../app/gui/source_spec.cpp" line="45"/>
        <source>%1 (baud: auto)</source>
        <translation>%1 (скорость: авто)</translation>
    </message>
    <message>
        <location filename="../app/gui/source_spec.cpp" line="46"/>
        <source>TCP %1</source>
        <translation>TCP %1</translation>
    </message>
    <message>
        <location filename="../app/gui/source_spec.cpp" line="47"/>
        <source>Replay %1</source>
        <translation>Воспроизведение %1</translation>
    </message>
    <message>
        <location filename="../app/gui/source_spec.cpp" line="48"/>
        <source>Simulated %1</source>
        <translation>Имитатор %1</translation>
    </message>
    <message>
        <location filename="../app/gui/source_spec.cpp" line="51"/>
        <source>No source</source>
        <translation>Нет источника</translation>
    </message>
</context>
<context>
    <name>gnss::ui::AttitudeView</name>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="42"/>
        <source>Attitude</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="45"/>
        <source>Roll</source>
        <translation>Крен</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="46"/>
        <source>Pitch</source>
        <translation>Тангаж</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="47"/>
        <source>Yaw</source>
        <translation>Рыскание</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="48"/>
        <source>Time (UTC)</source>
        <translation>Время (UTC)</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="51"/>
        <source>Acceleration</source>
        <translation>Ускорение</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="54"/>
        <source>North</source>
        <translation>Север</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="55"/>
        <source>East</source>
        <translation>Восток</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="56"/>
        <source>Down</source>
        <translation>Вниз</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="61"/>
        <source>Time marks (newest first)</source>
        <translation>Метки времени (новые сверху)</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="68"/>
        <source>Counter</source>
        <translation>Счётчик</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="68"/>
        <source>GPS time of week (s)</source>
        <translation>Время недели GPS (с)</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="68"/>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="69"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="69"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="69"/>
        <source>Altitude MSL (m)</source>
        <translation>Высота над уровнем моря (м)</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="105"/>
        <source>m/s²</source>
        <translation>м/с²</translation>
    </message>
    <message>
        <location filename="../ui/views/attitude_view.cpp" line="123"/>
        <source>No time marks yet</source>
        <translation>Меток времени пока нет</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/views/attitude_view.cpp" line="124"/>
        <source>%n time mark(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gnss::ui::ChartsView</name>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="106"/>
        <source>Series</source>
        <translation>Ряды</translation>
    </message>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="118"/>
        <source>Window</source>
        <translation>Окно</translation>
    </message>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="123"/>
        <source> min</source>
        <translation> мин</translation>
    </message>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="307"/>
        <source>minutes before the latest epoch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/charts_view.cpp" line="308"/>
        <source>seconds before the latest epoch</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::ui::ConsoleView</name>
    <message>
        <location filename="../ui/views/console_view.cpp" line="32"/>
        <source>Filter by address (e.g. GGA|PNVG)</source>
        <translation>Фильтр по адресу (например, GGA|PNVG)</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="38"/>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="44"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="46"/>
        <source>Show the raw bytes received, including binary data</source>
        <translation>Показать принятые байты, включая двоичные данные</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="51"/>
        <source>Clear</source>
        <translation>Очистить</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="91"/>
        <source>Command to send, e.g. $PNVGVER (the checksum is added)</source>
        <translation>Команда для отправки, например $PNVGVER (контрольная сумма добавляется)</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="101"/>
        <source>Send</source>
        <translation>Отправить</translation>
    </message>
    <message>
        <location filename="../ui/views/console_view.cpp" line="134"/>
        <source>Not sent: %1</source>
        <translation>Не отправлено: %1</translation>
    </message>
</context>
<context>
    <name>gnss::ui::CoordinateEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="222"/>
        <source> m (X)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="223"/>
        <source> m (Y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="224"/>
        <source> m (Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="232"/>
        <source> m (ellipsoid)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::ui::DeviationView</name>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="84"/>
        <source>No position yet</source>
        <translation>Координат пока нет</translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="123"/>
        <source>East (m)</source>
        <translation>Восток (м)</translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="128"/>
        <source>North (m)</source>
        <translation>Север (м)</translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="152"/>
        <location filename="../ui/views/deviation_view.cpp" line="260"/>
        <source>CEP50</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="153"/>
        <location filename="../ui/views/deviation_view.cpp" line="261"/>
        <source>CEP95</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="154"/>
        <location filename="../ui/views/deviation_view.cpp" line="262"/>
        <source>2DRMS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="219"/>
        <source>Reference</source>
        <translation>Опорная точка</translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="221"/>
        <source>Centre on a known position instead of the mean of the positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="224"/>
        <source>latitude, e.g. 55.7512 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="227"/>
        <source>longitude, e.g. 37.6181 E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="232"/>
        <source>How many of the latest positions are kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="233"/>
        <source>Reset</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="239"/>
        <location filename="../ui/views/deviation_view.cpp" line="263"/>
        <source>Points</source>
        <translation>Точки</translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="264"/>
        <source>Centre:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="269"/>
        <source>Mean offset:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="363"/>
        <source>Reference not used: type degrees such as 55.75123456 N and 37.61812345 E (or signed, -33.9 for south). Centred on the mean.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="382"/>
        <source>reference %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="382"/>
        <source>mean %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/deviation_view.cpp" line="387"/>
        <source>%1 east, %2 north</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::ui::FixView</name>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="30"/>
        <source>Degrees</source>
        <translation>Градусы</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="30"/>
        <source>Deg min sec</source>
        <translation>Град. мин. сек.</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="37"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="38"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="39"/>
        <source>Altitude (sea level)</source>
        <translation>Высота (над уровнем моря)</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="40"/>
        <source>Altitude (ellipsoid)</source>
        <translation>Высота (над эллипсоидом)</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="41"/>
        <source>Satellites used / in view</source>
        <translation>Спутники: в решении / видимые</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="42"/>
        <source>PDOP / HDOP / VDOP</source>
        <translation>PDOP / HDOP / VDOP</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="43"/>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="44"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="45"/>
        <source>Course</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="46"/>
        <source>Age of corrections</source>
        <translation>Возраст поправок</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="47"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="84"/>
        <source>No data</source>
        <translation>Нет данных</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="92"/>
        <location filename="../ui/views/fix_view.cpp" line="93"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="110"/>
        <source>%1 m/s  (%2 km/h)</source>
        <translation>%1 м/с  (%2 км/ч)</translation>
    </message>
    <message>
        <location filename="../ui/views/fix_view.cpp" line="116"/>
        <source>s</source>
        <translation>с</translation>
    </message>
</context>
<context>
    <name>gnss::ui::MessageStatsModel</name>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="52"/>
        <source>Address</source>
        <translation>Адрес</translation>
    </message>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="53"/>
        <source>Count</source>
        <translation>Количество</translation>
    </message>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="54"/>
        <source>Rate (Hz)</source>
        <translation>Частота (Гц)</translation>
    </message>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="55"/>
        <source>Last seen (UTC)</source>
        <translation>Последнее (UTC)</translation>
    </message>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="56"/>
        <source>Checksum errors</source>
        <translation>Ошибки КС</translation>
    </message>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="57"/>
        <source>Decode errors</source>
        <translation>Ошибки разбора</translation>
    </message>
    <message>
        <location filename="../ui/models/message_stats_model.cpp" line="58"/>
        <source>Unknown</source>
        <translation>Неизвестные</translation>
    </message>
</context>
<context>
    <name>gnss::ui::ReceiverInfoView</name>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="48"/>
        <source>Item</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="48"/>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="95"/>
        <source>Receiver: not identified yet</source>
        <translation>Приёмник: ещё не опознан</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="97"/>
        <source>&lt;b&gt;%1 %2&lt;/b&gt;&lt;br&gt;Firmware: %3%4</source>
        <translation>&lt;b&gt;%1 %2&lt;/b&gt;&lt;br&gt;Прошивка: %3%4</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="101"/>
        <source>&lt;br&gt;Hardware: %1</source>
        <translation>&lt;br&gt;Аппаратура: %1</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="104"/>
        <source>Jamming: not reported</source>
        <translation>Помехи: не сообщаются</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="107"/>
        <source>Jamming: DETECTED</source>
        <translation>Помехи: ОБНАРУЖЕНЫ</translation>
    </message>
    <message>
        <location filename="../ui/views/receiver_info_view.cpp" line="110"/>
        <source>Jamming: none detected</source>
        <translation>Помехи: не обнаружены</translation>
    </message>
</context>
<context>
    <name>gnss::ui::RtkView</name>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="46"/>
        <source>This receiver has not reported RTK information.</source>
        <translation>Приёмник не сообщал сведений RTK.</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="66"/>
        <source>Mode:</source>
        <translation>Режим:</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="74"/>
        <source>Alarm when corrections are older than</source>
        <translation>Тревога, если поправки старше</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="80"/>
        <source> s</source>
        <translation> с</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="87"/>
        <source>Base station</source>
        <translation>Базовая станция</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="88"/>
        <source>Correction age</source>
        <translation>Возраст поправок</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="89"/>
        <source>Distance to base</source>
        <translation>Расстояние до базы</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="90"/>
        <source>Base station id</source>
        <translation>Номер базовой станции</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="91"/>
        <source>RTCM messages</source>
        <translation>Сообщения RTCM</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="92"/>
        <source>RTCM good</source>
        <translation>RTCM без ошибок</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="93"/>
        <source>RTCM errors</source>
        <translation>Ошибки RTCM</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="96"/>
        <source>Baseline base → rover</source>
        <translation>Базовая линия база → ровер</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="97"/>
        <location filename="../ui/views/rtk_view.cpp" line="109"/>
        <source>North</source>
        <translation>Север</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="98"/>
        <location filename="../ui/views/rtk_view.cpp" line="110"/>
        <source>East</source>
        <translation>Восток</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="99"/>
        <location filename="../ui/views/rtk_view.cpp" line="111"/>
        <source>Vertical</source>
        <translation>Вертикаль</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="100"/>
        <location filename="../ui/views/rtk_view.cpp" line="108"/>
        <source>Length</source>
        <translation>Длина</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="101"/>
        <source>Course</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="102"/>
        <location filename="../ui/views/rtk_view.cpp" line="107"/>
        <source>Pitch</source>
        <translation>Тангаж</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="105"/>
        <source>Heading (antenna baseline)</source>
        <translation>Курс (линия антенн)</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="106"/>
        <location filename="../ui/views/rtk_view.cpp" line="121"/>
        <source>Heading</source>
        <translation>Курс</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="114"/>
        <source>Standard deviations</source>
        <translation>СКО</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="115"/>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="116"/>
        <source>Longitude</source>
        <translation>Долгота</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="117"/>
        <source>Height</source>
        <translation>Высота</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="118"/>
        <source>Velocity north</source>
        <translation>Скорость на север</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="119"/>
        <source>Velocity east</source>
        <translation>Скорость на восток</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="120"/>
        <source>Velocity up</source>
        <translation>Скорость вверх</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="124"/>
        <source>Receiver DOPs</source>
        <translation>Геометрические факторы приёмника</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="125"/>
        <source>GDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="126"/>
        <source>PDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="127"/>
        <source>HDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="128"/>
        <source>VDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="129"/>
        <source>TDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="130"/>
        <source>NDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="131"/>
        <source>EDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="190"/>
        <source>Autonomous</source>
        <translation>Автономный</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="191"/>
        <source>Differential</source>
        <translation>Дифференциальный</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="209"/>
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="209"/>
        <source>m/s</source>
        <translation>м/с</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="215"/>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="261"/>
        <source>Correction age: %1</source>
        <translation>Возраст поправок: %1</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="263"/>
        <source>Corrections too old: %1 s &gt; %2 s</source>
        <translation>Поправки устарели: %1 с &gt; %2 с</translation>
    </message>
    <message>
        <location filename="../ui/views/rtk_view.cpp" line="267"/>
        <source>Corrections OK: %1 s</source>
        <translation>Поправки в норме: %1 с</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SatelliteModel</name>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="61"/>
        <source>yes</source>
        <translation>да</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="61"/>
        <source>no</source>
        <translation>нет</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="76"/>
        <source>System</source>
        <translation>Система</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="77"/>
        <source>Satellite</source>
        <translation>Спутник</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="78"/>
        <source>Signal</source>
        <translation>Сигнал</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="79"/>
        <source>Elev. (°)</source>
        <translation>Угол места (°)</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="80"/>
        <source>Azim. (°)</source>
        <translation>Азимут (°)</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="81"/>
        <source>SNR (dB-Hz)</source>
        <translation>С/Ш (дБГц)</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="82"/>
        <source>Used</source>
        <translation>В решении</translation>
    </message>
    <message>
        <location filename="../ui/models/satellite_model.cpp" line="83"/>
        <source>Last seen (UTC)</source>
        <translation>Последнее (UTC)</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="209"/>
        <source>Range: %1 to %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::ui::SettingsView</name>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="60"/>
        <source>Read</source>
        <translation>Прочитать</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="61"/>
        <source>Read every setting the receiver reports</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="62"/>
        <source>Apply</source>
        <translation>Применить</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="63"/>
        <source>Send the edited values (only what differs), then read them back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="64"/>
        <source>Revert</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="65"/>
        <source>Forget the edits: show the receiver&apos;s values again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="66"/>
        <source>Save to flash</source>
        <translation>Сохранить во флэш</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="67"/>
        <source>Restore defaults</source>
        <translation>Заводские настройки</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="69"/>
        <source>Reset</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="72"/>
        <source>Presets</source>
        <translation>Предустановки</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="75"/>
        <location filename="../ui/settings/settings_view.cpp" line="114"/>
        <source>Profile</source>
        <translation>Профиль</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="78"/>
        <source>Import and compare...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="79"/>
        <source>Import settings profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="80"/>
        <location filename="../ui/settings/settings_view.cpp" line="86"/>
        <source>Settings profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="84"/>
        <source>Export...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="85"/>
        <source>Export settings profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="91"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="110"/>
        <source>Command / setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="110"/>
        <source>Outcome</source>
        <translation>Результат</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="110"/>
        <source>Detail</source>
        <translation>Подробности</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="114"/>
        <source>Setting</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="114"/>
        <source>Receiver</source>
        <translation>Приёмник</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="116"/>
        <source>Outcomes</source>
        <translation>Результаты</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="117"/>
        <source>Profile difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="177"/>
        <source>The %1 receiver has no settings this program knows.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="179"/>
        <source>Connect to a receiver: its settings appear here.</source>
        <translation>Подключите приёмник: здесь появятся его настройки.</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="232"/>
        <source>From %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="234"/>
        <source>Convert the %1 position to this form (WGS-84)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="259"/>
        <source>%1: select a setting to see its help.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="266"/>
        <source>Receiver: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="309"/>
        <source>Range: %1 to %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="314"/>
        <source>Default: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="315"/>
        <source>Written with: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="316"/>
        <source>Read back: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="318"/>
        <source>cannot be read back (write-only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="346"/>
        <source>Reading the receiver&apos;s settings...</source>
        <translation>Чтение настроек приёмника...</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="353"/>
        <source>Nothing to apply: no value was changed.</source>
        <translation>Нечего применять: значения не изменены.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/settings/settings_view.cpp" line="356"/>
        <source>Applying %n setting(s)...</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="371"/>
        <source>Edits reverted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="378"/>
        <source>This receiver has no such command.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="383"/>
        <source>%1 on the %2?

%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="386"/>
        <source>%1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/settings/settings_view.cpp" line="401"/>
        <source>Preset &quot;%1&quot; loaded: %n setting(s) differ from the receiver. Apply sends them.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="428"/>
        <source>The receiver already has every setting of %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/settings/settings_view.cpp" line="429"/>
        <source>%n setting(s) of the profile differ from the receiver (model %1, firmware %2); they are loaded as edits: Apply sends them.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="439"/>
        <source>Not connected to a receiver.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/settings/settings_view.cpp" line="444"/>
        <source>%n setting(s) exported to %1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="451"/>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="451"/>
        <source>problems</source>
        <translation>есть ошибки</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="464"/>
        <source>receiver reports %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="475"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="477"/>
        <source>%1: cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="479"/>
        <source>Nothing to send: the receiver already has these values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="481"/>
        <source>%1: %2 command(s) failed, %3 setting(s) did not take; see Outcomes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/settings/settings_view.cpp" line="486"/>
        <source>%1: done (%n command(s)).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="504"/>
        <source>Write the settings in force to the receiver&apos;s flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/settings/settings_view.cpp" line="505"/>
        <source>This receiver has no command to save its settings</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::ui::SignalLevelsView</name>
    <message>
        <location filename="../ui/views/signal_levels_view.cpp" line="89"/>
        <source>No satellites in view</source>
        <translation>Нет видимых спутников</translation>
    </message>
</context>
<context>
    <name>gnss::ui::SkyPlotView</name>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="92"/>
        <source>%1: SNR %2 dB-Hz%3</source>
        <translation>%1: С/Ш %2 дБГц%3</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="94"/>
        <source>, used</source>
        <translation>, в решении</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="103"/>
        <source>%1 (%2)
elevation %3°, azimuth %4°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="147"/>
        <source>N</source>
        <translation>С</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="148"/>
        <source>S</source>
        <translation>Ю</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="149"/>
        <source>E</source>
        <translation>В</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="150"/>
        <source>W</source>
        <translation>З</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="242"/>
        <source>Show tracks</source>
        <translation>Показывать треки</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="246"/>
        <source>Show labels</source>
        <translation>Показывать подписи</translation>
    </message>
    <message>
        <location filename="../ui/views/sky_plot_view.cpp" line="250"/>
        <source>Constellations</source>
        <translation>Системы</translation>
    </message>
</context>
<context>
    <name>gnss::ui::TextEditor</name>
    <message>
        <location filename="../ui/settings/setting_editors.cpp" line="166"/>
        <source>items separated by &apos;;&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>gnss::ui::TimeSeriesModel</name>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="145"/>
        <location filename="../ui/models/time_series_model.cpp" line="181"/>
        <source>Satellites used</source>
        <translation>Спутники в решении</translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="146"/>
        <source>HDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="147"/>
        <source>PDOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="148"/>
        <location filename="../ui/models/time_series_model.cpp" line="183"/>
        <source>Fix type</source>
        <translation>Тип решения</translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="149"/>
        <source>Std. dev. latitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="150"/>
        <source>Std. dev. longitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="151"/>
        <source>Std. dev. height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="152"/>
        <source>Baseline length</source>
        <translation>Длина базовой линии</translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="153"/>
        <source>Altitude above sea level</source>
        <translation>Высота над уровнем моря</translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="154"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="158"/>
        <source>Mean SNR %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="182"/>
        <source>DOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="184"/>
        <source>Mean SNR (dB-Hz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="185"/>
        <source>Standard deviation (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="186"/>
        <source>Baseline length (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="187"/>
        <source>Altitude above sea level (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/models/time_series_model.cpp" line="188"/>
        <source>Speed (m/s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
