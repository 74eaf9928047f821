// Standard sentence encoders (see nmea_encoders.h). Layouts follow NMEA 0183 4.11 and the field
// diagrams above each decoder in this folder.
#include "nmea/nmea_encoders.h"

#include "core/sentence_builder.h"

#include <cmath>
#include <cstdio>

namespace gnss::nmea {

namespace {

class Body {
public:
    Body(std::string_view talker, std::string_view type) {
        s_.append(talker);
        s_.append(type);
    }
    Body &text(std::string_view v) {
        s_.push_back(',');
        s_.append(v);
        return *this;
    }
    Body &raw(std::string_view v) { // already comma-separated fields ("ddmm.mm,N")
        s_.push_back(',');
        s_.append(v);
        return *this;
    }
    Body &real(std::optional<double> v, int decimals) {
        return text(v ? formatFixed(*v, decimals) : std::string());
    }
    Body &integer(std::optional<int> v, int width = 0) {
        if (!v) return text({});
        char buf[16];
        std::snprintf(buf, sizeof buf, "%0*d", width, *v);
        return text(buf);
    }
    Body &letter(std::optional<char> v) { return text(v ? std::string(1, *v) : std::string()); }
    Body &time(const std::optional<TimeOfDay> &t, int decimals) {
        return text(t ? formatTime(*t, decimals) : std::string());
    }
    // Latitude and longitude: four fields, ddmm.mmmm,N,dddmm.mmmm,E.
    Body &position(std::optional<double> lat, std::optional<double> lon, const EncodeFormat &f) {
        return raw(formatLatitude(lat, f.positionDecimals))
                .raw(formatLongitude(lon, f.positionDecimals));
    }
    // What GGA and GNS both report of the solution: satellites used, HDOP, altitude above MSL,
    // geoid separation (GGA follows each height with its unit M), differential age and station.
    template <class Fix> Body &solution(const Fix &m, bool heightUnits) {
        integer(m.satsUsed, 2).real(m.hdop, 1).real(m.altMsl, 3);
        if (heightUnits) text(m.altMsl ? "M" : "");
        real(m.geoidSep, 3);
        if (heightUnits) text(m.geoidSep ? "M" : "");
        return real(m.dgpsAge, 1).integer(m.dgpsStation, 4);
    }
    // Each row's field of `m` (core/field_table.h): a time or a position with the format's
    // decimals, a real with the row's, a letter, a number, text.
    template <class M, class Rows>
    Body &rows(const M &m, const Rows &table, const EncodeFormat &f) {
        for (const auto &row : table)
            std::visit([&](auto p) { add(m.*p, row.layout, row.form, f); }, row.member);
        return *this;
    }
    std::string build() const { return buildSentence(s_); }

private:
    void add(const std::optional<TimeOfDay> &t, const FieldLayout &, FieldForm,
             const EncodeFormat &f) {
        time(t, f.timeDecimals);
    }
    void add(std::optional<double> v, const FieldLayout &l, FieldForm form, const EncodeFormat &f) {
        if (form == FieldForm::Latitude)
            raw(formatLatitude(v, f.positionDecimals));
        else if (form == FieldForm::Longitude)
            raw(formatLongitude(v, f.positionDecimals));
        else
            real(v, l.decimals);
    }
    void add(std::optional<char> v, const FieldLayout &, FieldForm, const EncodeFormat &) {
        letter(v);
    }
    void add(std::optional<int> v, const FieldLayout &, FieldForm, const EncodeFormat &) {
        integer(v);
    }
    void add(std::optional<std::int64_t> v, const FieldLayout &, FieldForm, const EncodeFormat &) {
        text(v ? std::to_string(*v) : std::string());
    }
    void add(std::optional<std::string_view> v, const FieldLayout &, FieldForm,
             const EncodeFormat &) {
        text(v.value_or(std::string_view()));
    }
    std::string s_;
};

std::string formatAngle(std::optional<double> v, int degreeDigits, int minuteDecimals, char pos,
                        char neg) {
    if (!v || !std::isfinite(*v)) return ",";
    const double a = std::fabs(*v);
    int deg = static_cast<int>(a);
    double minutes = (a - deg) * 60.0;
    // Round at the printed precision first so 59.99999 never prints as "60.0000".
    const double scale = std::pow(10.0, minuteDecimals);
    minutes = std::round(minutes * scale) / scale;
    if (minutes >= 60.0) {
        minutes -= 60.0;
        ++deg;
    }
    char buf[48];
    const int width = minuteDecimals > 0 ? minuteDecimals + 3 : 2;
    std::snprintf(buf, sizeof buf, "%0*d%0*.*f,%c", degreeDigits, deg, width, minuteDecimals,
                  minutes, *v < 0 ? neg : pos);
    return buf;
}

} // namespace

TimeOfDay timeOfDay(double secondsOfDay, int decimals) {
    double s = std::fmod(secondsOfDay, 86400.0);
    if (s < 0) s += 86400.0;
    TimeOfDay t;
    t.nanos = static_cast<std::int64_t>(std::llround(s * 1e9));
    t.decimals = static_cast<std::uint8_t>(decimals);
    return t;
}

std::string formatTime(const TimeOfDay &t, int decimals) {
    // Round to the printed precision in integer nanoseconds (no 59.999 → "60").
    std::int64_t unit = 1'000'000'000;
    for (int i = 0; i < decimals && i < 9; ++i) unit /= 10;
    std::int64_t n = (t.nanos + unit / 2) / unit * unit;
    n %= 86'400'000'000'000LL;
    const int h = static_cast<int>(n / 3'600'000'000'000LL);
    const int m = static_cast<int>(n / 60'000'000'000LL % 60);
    const int s = static_cast<int>(n / 1'000'000'000LL % 60);
    if (decimals > 9) decimals = 9;
    char buf[48];
    if (decimals <= 0) {
        std::snprintf(buf, sizeof buf, "%02d%02d%02d", h, m, s);
    } else {
        const std::int64_t frac = (n % 1'000'000'000LL) / unit;
        std::snprintf(buf, sizeof buf, "%02d%02d%02d.%0*lld", h, m, s, decimals & 15,
                      static_cast<long long>(frac));
    }
    return buf;
}

std::string formatLatitude(std::optional<double> lat, int minuteDecimals) {
    return formatAngle(lat, 2, minuteDecimals, 'N', 'S');
}

std::string formatLongitude(std::optional<double> lon, int minuteDecimals) {
    return formatAngle(lon, 3, minuteDecimals, 'E', 'W');
}

std::string formatDate(const Date &d) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%02d%02d%02d", d.day, d.month, d.year % 100);
    return buf;
}

// $--GGA,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx
std::string encodeGga(std::string_view talker, const Gga &m, const EncodeFormat &f) {
    Body b(talker, "GGA");
    b.time(m.time, f.timeDecimals).position(m.lat, m.lon, f).integer(m.quality).solution(m, true);
    return b.build();
}

// $--GLL,llll.ll,a,yyyyy.yy,a,hhmmss.ss,A,a
std::string encodeGll(std::string_view talker, const Gll &m, const EncodeFormat &f) {
    return Body(talker, "GLL").rows(m, Gll::kFields, f).build();
}

// $--GNS,hhmmss.ss,llll.ll,a,yyyyy.yy,a,c--c,xx,x.x,x.x,x.x,x.x,x.x,a
std::string encodeGns(std::string_view talker, const Gns &m, const EncodeFormat &f) {
    Body b(talker, "GNS");
    b.time(m.time, f.timeDecimals).position(m.lat, m.lon, f).text(m.mode).solution(m, false);
    if (m.navStatus) b.letter(m.navStatus);
    return b.build();
}

// $--GSA,a,x,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,x.x,x.x,x.x[,h]
std::string encodeGsa(std::string_view talker, const Gsa &m) {
    Body b(talker, "GSA");
    b.letter(m.mode).integer(m.fix);
    const std::size_t slots = m.idCount > 12 ? m.idCount : 12;
    for (std::size_t i = 0; i < slots; ++i)
        b.integer(i < m.idCount ? std::optional<int>(m.ids[i]) : std::nullopt, 2);
    b.real(m.pdop, 1).real(m.hdop, 1).real(m.vdop, 1);
    if (m.systemId) b.integer(m.systemId);
    return b.build();
}

// $--GSV,x,x,xx,xx,xx,xxx,xx,...[,h]
std::string encodeGsv(std::string_view talker, const Gsv &m) {
    Body b(talker, "GSV");
    b.integer(m.total).integer(m.index).integer(m.inView, 2);
    for (std::size_t i = 0; i < m.satelliteCount; ++i) {
        const GsvSatellite &s = m.satellites[i];
        b.integer(s.id, 2).integer(s.elevation, 2).integer(s.azimuth, 3).integer(s.snr, 2);
    }
    if (m.signalId) b.integer(m.signalId);
    return b.build();
}

std::vector<std::string> encodeGsvGroup(std::string_view talker,
                                        std::span<const GsvSatellite> satellites,
                                        std::optional<int> signalId) {
    const int n = static_cast<int>(satellites.size());
    const int total = n == 0 ? 1 : (n + 3) / 4;
    std::vector<std::string> out;
    out.reserve(static_cast<std::size_t>(total));
    for (int k = 0; k < total; ++k) {
        Gsv m;
        m.total = total;
        m.index = k + 1;
        m.inView = n;
        m.signalId = signalId;
        for (int i = k * 4; i < n && i < k * 4 + 4; ++i)
            m.satellites[m.satelliteCount++] = satellites[static_cast<std::size_t>(i)];
        out.push_back(encodeGsv(talker, m));
    }
    return out;
}

// $--RMC,hhmmss.ss,A,llll.ll,a,yyyyy.yy,a,x.x,x.x,ddmmyy,x.x,a,a[,a]
std::string encodeRmc(std::string_view talker, const Rmc &m, const EncodeFormat &f) {
    Body b(talker, "RMC");
    b.time(m.time, f.timeDecimals)
            .letter(m.status)
            .position(m.lat, m.lon, f)
            .real(m.sogKnots, 2)
            .real(m.cog, 2)
            .text(m.date ? formatDate(*m.date) : std::string())
            .real(m.magVar ? std::optional<double>(std::fabs(*m.magVar)) : std::nullopt, 1)
            .text(m.magVar ? (*m.magVar < 0 ? "W" : "E") : "")
            .letter(m.mode);
    if (m.navStatus) b.letter(m.navStatus);
    return b.build();
}

// $--VTG,x.x,T,x.x,M,x.x,N,x.x,K,a
std::string encodeVtg(std::string_view talker, const Vtg &m) {
    Body b(talker, "VTG");
    b.real(m.cogTrue, 2)
            .text("T")
            .real(m.cogMagnetic, 2)
            .text("M")
            .real(m.sogKnots, 2)
            .text("N")
            .real(m.sogKmh, 2)
            .text("K")
            .letter(m.mode);
    return b.build();
}

// $--ZDA,hhmmss.ss,xx,xx,xxxx,xx,xx
std::string encodeZda(std::string_view talker, const Zda &m, const EncodeFormat &f) {
    Body b(talker, "ZDA");
    b.time(m.time, f.timeDecimals)
            .integer(m.date ? std::optional<int>(m.date->day) : std::nullopt, 2)
            .integer(m.date ? std::optional<int>(m.date->month) : std::nullopt, 2)
            .integer(m.date ? std::optional<int>(m.date->year) : std::nullopt, 4)
            .integer(m.tzHours, 2)
            .integer(m.tzMinutes, 2);
    return b.build();
}

// $--HDT,x.x,T
std::string encodeHdt(std::string_view talker, const Hdt &m) {
    Body b(talker, "HDT");
    b.real(m.heading, 2).text("T");
    return b.build();
}

// $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x
std::string encodeGst(std::string_view talker, const Gst &m, const EncodeFormat &f) {
    return Body(talker, "GST").rows(m, Gst::kFields, f).build();
}

// $--TXT,xx,xx,xx,c--c
std::string encodeTxt(std::string_view talker, const Txt &m) {
    Body b(talker, "TXT");
    b.integer(m.total, 2).integer(m.number, 2).integer(m.id, 2).text(m.text);
    return b.build();
}

} // namespace gnss::nmea
