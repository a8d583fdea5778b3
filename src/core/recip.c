/*
 * recip.c - reciprocals without a divide: the perspective weight 1/w of
 * each vertex (mote__inverse_w), the pixel loop's reciprocal on cores
 * with no 64-bit divide (MOTE_RECIP_BY_TABLE, internal.h), and division
 * by a reciprocal (mote__divide) for the integer vertex stage and, on
 * cores without a divide instruction, setup's depth plane.
 *
 * mote__recip_lookup(m) is floor(2^61 / m) for m in [2^30, 2^31), exactly:
 * a first guess interpolated in a table of 257 values, one Newton step and
 * one correction. The table holds floor(2^61 / (2^30 + i 2^22)) less
 * 12288, so that the chord between two entries, which lies above
 * the convex curve by up to about 2^13, stays below it: the guess y0 then
 * errs low by less than 2^-16 of its value, the step's error is its square
 * (under half a unit) plus its own truncations (under one), and one
 * comparison of the remainder, which fits in 32 bits, finishes it.
 * tests/test_recip.c checks all 2^30 mantissas against a division.
 */
#include "internal.h"

const uint32_t mote__recip_table[257] = {
    2147471360u, 2139115392u, 2130824199u, 2122597032u, 2114433150u, 2106331826u,
    2098292345u, 2090314000u, 2082396097u, 2074537953u, 2066738892u, 2058998250u,
    2051315375u, 2043689622u, 2036120356u, 2028606951u, 2021148792u, 2013745272u,
    2006395791u, 1999099762u, 1991856602u, 1984665740u, 1977526610u, 1970438657u,
    1963401333u, 1956414095u, 1949476413u, 1942587761u, 1935747620u, 1928955480u,
    1922210837u, 1915513195u, 1908862065u, 1902256964u, 1895697415u, 1889182948u,
    1882713102u, 1876287418u, 1869905446u, 1863566742u, 1857270867u, 1851017388u,
    1844805879u, 1838635918u, 1832507091u, 1826418987u, 1820371201u, 1814363335u,
    1808394994u, 1802465790u, 1796575339u, 1790723262u, 1784909185u, 1779132740u,
    1773393563u, 1767691293u, 1762025577u, 1756396063u, 1750802405u, 1745244264u,
    1739721300u, 1734233181u, 1728779579u, 1723360169u, 1717974630u, 1712622646u,
    1707303904u, 1702018095u, 1696764915u, 1691544062u, 1686355239u, 1681198152u,
    1676072510u, 1670978027u, 1665914420u, 1660881409u, 1655878717u, 1650906072u,
    1645963202u, 1641049843u, 1636165729u, 1631310601u, 1626484202u, 1621686278u,
    1616916576u, 1612174849u, 1607460852u, 1602774341u, 1598115077u, 1593482824u,
    1588877347u, 1584298414u, 1579745797u, 1575219270u, 1570718608u, 1566243592u,
    1561794001u, 1557369621u, 1552970237u, 1548595638u, 1544245616u, 1539919963u,
    1535618477u, 1531340954u, 1527087195u, 1522857002u, 1518650181u, 1514466538u,
    1510305882u, 1506168024u, 1502052777u, 1497959956u, 1493889380u, 1489840866u,
    1485814236u, 1481809312u, 1477825921u, 1473863888u, 1469923043u, 1466003215u,
    1462104238u, 1458225945u, 1454368172u, 1450530756u, 1446713538u, 1442916357u,
    1439139057u, 1435381481u, 1431643477u, 1427924890u, 1424225571u, 1420545370u,
    1416884139u, 1413241732u, 1409618004u, 1406012811u, 1402426012u, 1398857467u,
    1395307036u, 1391774582u, 1388259969u, 1384763061u, 1381283726u, 1377821832u,
    1374377246u, 1370949841u, 1367539487u, 1364146059u, 1360769429u, 1357409474u,
    1354066071u, 1350739097u, 1347428432u, 1344133956u, 1340855550u, 1337593098u,
    1334346483u, 1331115590u, 1327900305u, 1324700516u, 1321516110u, 1318346977u,
    1315193008u, 1312054093u, 1308930126u, 1305820999u, 1302726607u, 1299646846u,
    1296581612u, 1293530803u, 1290494317u, 1287472053u, 1284463912u, 1281469795u,
    1278489604u, 1275523243u, 1272570614u, 1269631623u, 1266706177u, 1263794180u,
    1260895542u, 1258010169u, 1255137972u, 1252278859u, 1249432743u, 1246599534u,
    1243779146u, 1240971490u, 1238176482u, 1235394035u, 1232624066u, 1229866490u,
    1227121225u, 1224388188u, 1221667298u, 1218958474u, 1216261636u, 1213576705u,
    1210903601u, 1208242248u, 1205592567u, 1202954481u, 1200327916u, 1197712796u,
    1195109046u, 1192516592u, 1189935361u, 1187365279u, 1184806276u, 1182258279u,
    1179721218u, 1177195022u, 1174679622u, 1172174948u, 1169680933u, 1167197507u,
    1164724605u, 1162262159u, 1159810104u, 1157368372u, 1154936900u, 1152515623u,
    1150104477u, 1147703398u, 1145312324u, 1142931192u, 1140559939u, 1138198506u,
    1135846831u, 1133504854u, 1131172514u, 1128849752u, 1126536510u, 1124232730u,
    1121938352u, 1119653320u, 1117377577u, 1115111066u, 1112853732u, 1110605517u,
    1108366369u, 1106136230u, 1103915049u, 1101702769u, 1099499339u, 1097304705u,
    1095118815u, 1092941616u, 1090773057u, 1088613086u, 1086461652u, 1084318705u,
    1082184196u, 1080058073u, 1077940288u, 1075830792u, 1073729536u,
};

uint32_t mote__recip_lookup(uint32_t m)
{
    const uint32_t y0 = mote__recip_guess(m);
    /* 0 <= e = 2^61 - m y0 < 2^45; y1 = y0 (1 + e / 2^61) */
    const uint64_t e = ((uint64_t)1 << 61) - mote__umul64(m, y0);
    uint32_t y = y0 + (uint32_t)(mote__umul64(y0, (uint32_t)(e >> 13)) >> 48);
    /* y is the floor or one less: the remainder 2^61 - m y is below 2m,
     * and in 32 bits it is the low word of -m y */
    y += 0u - m * y >= m;
    return y;
}

void mote__inverse_w(float w, mote__svert *out)
{
    /* w = M 2^(e - 157) with M = the 24-bit mantissa 2^7, in [2^30, 2^31),
     * so 1/w = (2^61 / M) 2^(96 - e); zero, denormals and the sign (a
     * vertex clipping drops) give some value, never a fault */
    const uint32_t bits = mote__float_bits(w);
    out->qm = mote__recip_lookup(((bits & 0x7fffffu) | 0x800000u) << 7);
    out->qe = (int32_t)((bits >> 23) & 0xff);
}

uint32_t mote__divisor_init(mote__divisor *v, uint32_t d)
{
    v->d = d;
    v->sh = 32 - mote__bitlen32(d);
    /* 2^63 / dn = 2 (2^61 / (dn / 2)), the exact reciprocal of dn's top
     * 31 bits: within 4 units */
    const uint32_t r = mote__recip_lookup((d << v->sh) >> 1);
    v->r = r >> 31 ? 0xffffffffu : r << 1;
    return r;
}

bool mote__divide(uint64_t n, const mote__divisor *v, uint32_t *q)
{
    /* n / d = n 2^sh r / 2^63 from n's top 32 bits, n' = n / 2^k: within
     * 2^-28 of it, so a few units, which the remainder then corrects. All
     * shifts are of 32-bit halves: a variable 64-bit shift is a libgcc
     * call on 32-bit cores. */
    const uint32_t lo = (uint32_t)n, hi = (uint32_t)(n >> 32);
    const int k = mote__bitlen32(hi), s = 63 - v->sh - k;
    if (s < 0)
        return false;
    const uint32_t top = k == 0 ? lo : k == 32 ? hi : lo >> k | hi << (32 - k);
    const uint64_t p = mote__umul64(top, v->r);
    const uint32_t pl = (uint32_t)p, ph = (uint32_t)(p >> 32);
    uint32_t e;
    if (s >= 32) {
        e = ph >> (s - 32);
    } else {
        if (ph >> s != 0)
            return false;
        e = s == 0 ? pl : pl >> s | ph << (32 - s);
    }
    uint64_t m = mote__umul64(e, v->d);
    while (m > n) {
        e--;
        m -= v->d;
    }
    while (n - m >= v->d) {
        if (e == 0xffffffffu)
            return false;
        e++;
        m += v->d;
    }
    *q = e;
    return true;
}

uint64_t mote__udiv64(uint64_t n, uint64_t d)
{
    if (d >> 32 == 0) {
        mote__divisor v;
        uint32_t q;
        mote__divisor_init(&v, (uint32_t)d);
        if (mote__divide(n, &v, &q))
            return q;
    }
    /* the rare rest (quotients or divisors past 32 bits) a bit at a time,
     * by shifts of one: a variable 64-bit shift is a libgcc call too */
    uint64_t q = 0, r = 0;
    for (int i = 0; i < 64; i++) {
        r = r << 1 | n >> 63;     /* r < d < 2^63: no bit lost */
        n <<= 1;
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1;
        }
    }
    return q;
}

bool mote__divide_floor(int64_t a, const mote__divisor *v, int64_t *q)
{
    const uint64_t u = a < 0 ? 0u - (uint64_t)a : (uint64_t)a;
    uint32_t m;
    if (!mote__divide(a < 0 ? u + v->d - 1 : u, v, &m))
        return false;
    *q = a < 0 ? -(int64_t)m : (int64_t)m;
    return true;
}
