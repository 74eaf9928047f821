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
    <name>gnss::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="15"/>
        <source>GNSS Workbench</source>
        <translation>GNSS Workbench</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="19"/>
        <source>Not connected</source>
        <translation>Нет подключения</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="26"/>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="27"/>
        <source>&amp;Open Log...</source>
        <translation>&amp;Открыть журнал...</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="30"/>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="33"/>
        <source>&amp;Receiver</source>
        <translation>&amp;Приёмник</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="35"/>
        <source>&amp;Connect</source>
        <translation>&amp;Подключить</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="35"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="36"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Отключить</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="36"/>
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="38"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="41"/>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="42"/>
        <source>&amp;About GNSS Workbench</source>
        <translation>&amp;О программе GNSS Workbench</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="43"/>
        <source>About &amp;Qt</source>
        <translation>О &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="48"/>
        <source>Open Log</source>
        <translation>Открыть журнал</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="49"/>
        <source>NMEA logs (*.nmea *.log *.txt);;All files (*)</source>
        <translation>Журналы NMEA (*.nmea *.log *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="54"/>
        <source>About GNSS Workbench</source>
        <translation>О программе GNSS Workbench</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="55"/>
        <source>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Configure and monitor NVS NV08C-RTK, GeoStar GeoS-5, Nemerix and NMEA-0183 receivers.</source>
        <translation>&lt;b&gt;GNSS Workbench&lt;/b&gt; %1&lt;br&gt;Настройка и мониторинг приёмников NVS NV08C-RTK, GeoStar GeoS-5, Nemerix и NMEA-0183.</translation>
    </message>
</context>
</TS>
