// Broadcast ephemerides: which satellite, which issue (week, IODE/IODC, toc/toe, health). The
// orbit and clock terms in between are skipped by their widths; the payload must hold them all.
#include "rtcm/message_decoders.h"

namespace gnss::rtcm {
namespace {

std::uint32_t u32(BitReader &r, unsigned bits) {
    return static_cast<std::uint32_t>(r.u(bits));
}

// 1019 GPS ephemeris (488 bits).
//
//   field                 DF    bits      field                 DF    bits
//   message number        002   12        Cus                   091   16
//   satellite id          009    6        sqrt(A)               092   32
//   week number           076   10        toe, 16 s             093   16
//   SV accuracy           077    4        Cic                   094   16
//   code on L2            078    2        OMEGA0                095   32
//   IDOT                  079   14        Cis                   096   16
//   IODE                  071    8        i0                    097   32
//   toc, 16 s             081   16        Crc                   098   16
//   af2                   082    8        omega                 099   32
//   af1                   083   16        OMEGADOT              100   24
//   af0                   084   22        tGD                   101    8
//   IODC                  085   10        SV health             102    6
//   Crs                   086   16        L2 P data flag        103    1
//   delta n               087   16        fit interval          137    1
//   M0                    088   32
//   Cuc                   089   16
//   e                     090   32
void decodeGps(BitReader &r, Ephemeris &e) {
    e.system = System::Gps;
    e.satellite = e.prn = u32(r, 6);
    e.week = u32(r, 10);
    r.skip(4 + 2 + 14);
    e.iode = u32(r, 8);
    e.tocSeconds = u32(r, 16) * 16;
    r.skip(8 + 16 + 22);
    e.iodc = u32(r, 10);
    r.skip(16 + 16 + 32 + 16 + 32 + 16 + 32);
    e.toeSeconds = u32(r, 16) * 16;
    r.skip(16 + 32 + 16 + 32 + 16 + 32 + 24 + 8);
    e.health = u32(r, 6);
    r.skip(1 + 1);
}

// 1020 GLONASS ephemeris (360 bits).
//
//   field                           DF    bits      field                     DF    bits
//   message number                  002   12        zn'  (intS)               117   24
//   satellite id (slot)             038    6        zn   (intS)               118   27
//   frequency channel + 7           040    5        zn'' (intS)               119    5
//   almanac health                  104    1        P3                        120    1
//   almanac health availability     105    1        gamma_n (intS)            121   11
//   P1                              106    2        P                         122    2
//   tk: hours 5, minutes 6, 30 s 1  107   12        ln (third string)         123    1
//   Bn MSB (health)                 108    1        tau_n (intS)              124   22
//   P2                              109    1        delta tau_n (intS)        125    5
//   tb, 15 min                      110    7        En                        126    5
//   xn'  (intS)                     111   24        P4                        127    1
//   xn   (intS)                     112   27        FT                        128    4
//   xn'' (intS)                     113    5        NT                        129   11
//   yn'  (intS)                     114   24        M                         130    2
//   yn   (intS)                     115   27        additional data           131    1
//   yn'' (intS)                     116    5        NA                        132   11
//                                                   tau_c (intS)              133   32
//                                                   N4                        134    5
//                                                   tau_GPS (intS)            135   22
//                                                   ln (fifth string)         136    1
//                                                   reserved                  001    7
void decodeGlonass(BitReader &r, Ephemeris &e) {
    e.system = System::Glonass;
    e.satellite = e.prn = u32(r, 6);
    e.frequencyChannel = static_cast<int>(r.u(5)) - 7;
    r.skip(1 + 1 + 2);
    const std::uint32_t hours = u32(r, 5);
    const std::uint32_t minutes = u32(r, 6);
    const std::uint32_t halfMinute = u32(r, 1);
    e.tkSeconds = hours * 3600 + minutes * 60 + halfMinute * 30;
    e.health = u32(r, 1);
    r.skip(1);
    e.tbMinutes = u32(r, 7) * 15;
    r.skip(3 * (24 + 27 + 5) + 1 + 11 + 2 + 1 + 22 + 5 + 5 + 1 + 4 + 11 + 2 + 1 + 11 + 32 + 5 + 22 +
           1 + 7);
}

// 1042 BeiDou ephemeris (511 bits).
//
//   field                 DF    bits      field                 DF    bits
//   message number        002   12        Cuc                   501   18
//   satellite id          488    6        e                     502   32
//   week number           489   13        Cus                   503   18
//   URAI                  490    4        sqrt(A)               504   32
//   IDOT                  491   14        toe, 8 s              505   17
//   AODE                  492    5        Cic                   506   18
//   toc, 8 s              493   17        OMEGA0                507   32
//   a2                    494   11        Cis                   508   18
//   a1                    495   22        i0                    509   32
//   a0                    496   24        Crc                   510   18
//   AODC                  497    5        omega                 511   32
//   Crs                   498   18        OMEGADOT              512   24
//   delta n               499   16        TGD1                  513   10
//   M0                    500   32        TGD2                  514   10
//                                         SV health             515    1
void decodeBeiDou(BitReader &r, Ephemeris &e) {
    e.system = System::BeiDou;
    e.satellite = e.prn = u32(r, 6);
    e.week = u32(r, 13);
    r.skip(4 + 14);
    e.iode = u32(r, 5);
    e.tocSeconds = u32(r, 17) * 8;
    r.skip(11 + 22 + 24);
    e.iodc = u32(r, 5);
    r.skip(18 + 16 + 32 + 18 + 32 + 18 + 32);
    e.toeSeconds = u32(r, 17) * 8;
    r.skip(18 + 32 + 18 + 32 + 18 + 32 + 24 + 10 + 10);
    e.health = u32(r, 1);
}

// 1044 QZSS ephemeris (485 bits).
//
//   field                 DF    bits      field                 DF    bits
//   message number        002   12        toe, 16 s             442   16
//   satellite id          429    4        Cic                   443   16
//   toc, 16 s             430   16        OMEGA0                444   32
//   af2                   431    8        Cis                   445   16
//   af1                   432   16        i0                    446   32
//   af0                   433   22        Crc                   447   16
//   IODE                  434    8        omega                 448   32
//   Crs                   435   16        OMEGADOT              449   24
//   delta n               436   16        IDOT                  450   14
//   M0                    437   32        codes on L2           451    2
//   Cuc                   438   16        week number           452   10
//   e                     439   32        URA                   453    4
//   Cus                   440   16        SV health             454    6
//   sqrt(A)               441   32        TGD                   455    8
//                                         IODC                  456   10
//                                         fit interval          457    1
void decodeQzss(BitReader &r, Ephemeris &e) {
    e.system = System::Qzss;
    e.satellite = u32(r, 4);
    e.prn = msmPrn(System::Qzss, e.satellite);
    e.tocSeconds = u32(r, 16) * 16;
    r.skip(8 + 16 + 22);
    e.iode = u32(r, 8);
    r.skip(16 + 16 + 32 + 16 + 32 + 16 + 32);
    e.toeSeconds = u32(r, 16) * 16;
    r.skip(16 + 32 + 16 + 32 + 16 + 32 + 24 + 14 + 2);
    e.week = u32(r, 10);
    r.skip(4);
    e.health = u32(r, 6);
    r.skip(8);
    e.iodc = u32(r, 10);
    r.skip(1);
}

// 1045 Galileo F/NAV (496 bits) and 1046 Galileo I/NAV (504 bits) ephemerides.
//
//   field                 DF    bits      field                 DF    bits
//   message number        002   12        sqrt(A)               303   32
//   satellite id          252    6        toe, 60 s             304   14
//   week number           289   12        Cic                   305   16
//   IODnav                290   10        OMEGA0                306   32
//   SISA                  291    8        Cis                   307   16
//   IDOT                  292   14        i0                    308   32
//   toc, 60 s             293   14        Crc                   309   16
//   af2                   294    6        omega                 310   32
//   af1                   295   21        OMEGADOT              311   24
//   af0                   296   31        BGD E5a/E1            312   10
//   Crs                   297   16        -- 1045 F/NAV --
//   delta n               298   16        E5a signal health     314    2
//   M0                    299   32        E5a data validity     315    1
//   Cuc                   300   16        reserved              001    7
//   e                     301   32        -- 1046 I/NAV --
//   Cus                   302   16        BGD E5b/E1            313   10
//                                         E5b signal health     316    2
//                                         E5b data validity     317    1
//                                         E1-B signal health    287    2
//                                         E1-B data validity    288    1
//                                         reserved              001    2
void decodeGalileo(BitReader &r, Ephemeris &e, bool inav) {
    e.system = System::Galileo;
    e.satellite = e.prn = u32(r, 6);
    e.week = u32(r, 12);
    e.iode = u32(r, 10);
    r.skip(8 + 14);
    e.tocSeconds = u32(r, 14) * 60;
    r.skip(6 + 21 + 31 + 16 + 16 + 32 + 16 + 32 + 16 + 32);
    e.toeSeconds = u32(r, 14) * 60;
    r.skip(16 + 32 + 16 + 32 + 16 + 32 + 24 + 10);
    if (inav) {
        r.skip(10);
        e.e5bHealth = u32(r, 2);
        e.e5bValidity = u32(r, 1);
        e.e1bHealth = u32(r, 2);
        e.e1bValidity = u32(r, 1);
        r.skip(2);
    } else {
        e.e5aHealth = u32(r, 2);
        e.e5aValidity = u32(r, 1);
        r.skip(7);
    }
}

} // namespace

void decodeEphemeris(BitReader &r, RtcmMessage &m) {
    Ephemeris e;
    switch (m.number) {
    case 1019: decodeGps(r, e); break;
    case 1020: decodeGlonass(r, e); break;
    case 1042: decodeBeiDou(r, e); break;
    case 1044: decodeQzss(r, e); break;
    case 1045: decodeGalileo(r, e, false); break;
    case 1046: decodeGalileo(r, e, true); break;
    default: return;
    }
    if (!r.ok()) {
        m.error = "truncated";
        return;
    }
    m.body = e;
}

} // namespace gnss::rtcm
