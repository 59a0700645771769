/* The byte sink the mesh writers share (mesh/sink.h). */
#include "mesh/sink.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

void bsi_sink_put(bsi_sink *s, const void *data, size_t n)
{
    if (s->f != NULL) {
        if (!s->err && fwrite(data, 1, n, s->f) != n)
            s->err = errno ? errno : EIO;
    } else if (s->buf != NULL) {
        if (s->len > s->cap || n > s->cap - s->len)
            s->err = 1;
        else if (n > 0)
            memcpy(s->buf + s->len, data, n);
    }
    s->len += n;
}

void bsi_sink_str(bsi_sink *s, const char *text)
{
    bsi_sink_put(s, text, strlen(text));
}

void bsi_sink_double(bsi_sink *s, double x, int digits)
{
    char raw[64], out[64];
    int n = snprintf(raw, sizeof raw, "%.*g", digits ? digits : 15, x);
    /* digits 0: the fewest of 15, 16 and 17 that read back to the same bits (17 always do); the
     * text is read back in the locale it was written in */
    for (int prec = 16; digits == 0 && prec <= 17 && n > 0 && (size_t)n < sizeof raw; prec++) {
        double back = strtod(raw, NULL);
        if (memcmp(&back, &x, sizeof x) == 0) // NOLINT(bugprone-suspicious-memory-comparison,cert-exp42-c,cert-flp37-c): bits, for -0
            break;
        n = snprintf(raw, sizeof raw, "%.*g", prec, x);
    }
    if (n < 0 || (size_t)n >= sizeof raw) {
        s->err = EIO;
        return;
    }
    /* The C locale's decimal point may be ',' or several bytes: whatever is not part of a number
     * in the "C" form (digits, sign, exponent) is the decimal point and becomes one '.'. */
    size_t k = 0;
    int in_point = 0;
    for (int i = 0; i < n; i++) {
        char c = raw[i];
        int keep = (c >= '0' && c <= '9') || c == '-' || c == '+' || c == 'e' || c == 'E';
        if (keep) {
            out[k++] = c;
            in_point = 0;
        } else if (!in_point) {
            out[k++] = '.';
            in_point = 1;
        }
    }
    bsi_sink_put(s, out, k);
}

void bsi_sink_uint(bsi_sink *s, size_t x)
{
    char digits[24];
    size_t k = sizeof digits;
    do {
        digits[--k] = (char)('0' + (int)(x % 10));
        x /= 10;
    } while (x != 0);
    bsi_sink_put(s, digits + k, sizeof digits - k);
}

void bsi_sink_u32le(bsi_sink *s, uint32_t x)
{
    unsigned char b[4] = {(unsigned char)(x & 0xffu), (unsigned char)((x >> 8) & 0xffu),
                          (unsigned char)((x >> 16) & 0xffu), (unsigned char)(x >> 24)};
    bsi_sink_put(s, b, 4);
}

void bsi_sink_f32le(bsi_sink *s, double x)
{
    float f = (float)x;
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    bsi_sink_u32le(s, bits);
}
