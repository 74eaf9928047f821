#pragma once
// Source tables the NTRIP tests read, shared with the fuzz seeds (tests/fuzz/gnss_fuzz_seeds.cpp)
// so that the corpus starts from the same tables.

namespace ntrip_test {

// A caster's table: STR records (one with extra fields, one of another format), CAS and NET.
inline constexpr char kSourceTable[] =
        "STR;MOSC00RUS0;Moscow;RTCM 3.2;1005(10),1074(1),1084(1),1230(10);2;GPS+GLO;IGS;RUS;"
        "55.75;37.62;0;0;NV08C-RTK;none;B;N;9600;misc;with;semicolons\r\n"
        "STR;VRS_RTCM3;Network VRS;RTCM 3;1004(1),1012(1);2;GPS+GLO;NET1;RUS;55.00;37.00;1;1;"
        "sNTRIP;none;B;Y;5000;\r\n"
        "STR;CMR;Old;CMR+;;2;GPS;NET1;RUS;56.00;38.00;0;0;gen;none;N;N;2400\r\n"
        "CAS;caster.example.org;2101;Example;Operator;0;RUS;55.7;37.6;fallback.example.org;"
        "2102;http://example.org\r\n"
        "NET;NET1;Operator;B;N;http://net;http://str;http://reg;none\r\n"
        "ENDSOURCETABLE\r\n";

// What Debian's str2str (RTKLIB 2.4.3 b34) sends for the mountpoint string of the tests.
inline constexpr char kRtklibSourceTable[] =
        "STR;MOUNT;MOUNT;RTCM 3.2;1005(10);2;GPS;LOCAL;XXX;0.00;0.00;0;0;sim;none;B;N;"
        "9600;\r\nENDSOURCETABLE\r\n";

} // namespace ntrip_test
