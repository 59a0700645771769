/*
 * Locale-independent decimal numbers for the .bpt format.
 *
 * Reading: the token is checked against the C grammar here, then copied into a buffer in which '.'
 * is replaced by the current locale's decimal point, and converted by strtod(). strtod() rounds
 * correctly (glibc, musl and the BSDs do), and since only digits, signs, 'e' and the locale's own
 * decimal point reach it, no locale-specific form (hex floats, "nan", grouping) can slip through.
 * Writing: "%.*g" with 15, 16 then 17 digits, keeping the first that reads back exactly; the
 * locale's decimal point is replaced by '.'. C99 only: no uselocale() needed.
 */
#include "io/internal.h"

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* The locale's decimal point as a string (it may be several bytes in a multibyte locale). */
static const char *locale_point(void)
{
    const struct lconv *lc = localeconv();
    return (lc && lc->decimal_point && lc->decimal_point[0]) ? lc->decimal_point : ".";
}

int bsi_parse_double(const char *tok, size_t len, double *out)
{
    /* Grammar: [+-] (digits [. [digits]] | . digits) [(e|E) [+-] digits] */
    size_t k = 0, ndig = 0;
    if (len > BSI_NUMBER_MAX)
        return -2;
    if (len == 0)
        return 0;
    if (tok[k] == '+' || tok[k] == '-')
        k++;
    while (k < len && is_digit(tok[k]))
        k++, ndig++;
    size_t dot = len;
    if (k < len && tok[k] == '.') {
        dot = k++;
        while (k < len && is_digit(tok[k]))
            k++, ndig++;
    }
    if (ndig == 0)
        return 0;
    if (k < len && (tok[k] == 'e' || tok[k] == 'E')) {
        k++;
        if (k < len && (tok[k] == '+' || tok[k] == '-'))
            k++;
        size_t edig = 0;
        while (k < len && is_digit(tok[k]))
            k++, edig++;
        if (edig == 0)
            return 0;
    }
    if (k != len)
        return 0;

    char buf[BSI_NUMBER_MAX + 16];
    const char *point = locale_point();
    size_t plen = strlen(point);
    if (plen > 15)
        return 0;
    size_t b = 0;
    for (k = 0; k < len; k++) {
        if (k == dot) {
            memcpy(buf + b, point, plen);
            b += plen;
        } else {
            buf[b++] = tok[k];
        }
    }
    buf[b] = '\0';
    char *end = NULL;
    double x = strtod(buf, &end);
    if (end != buf + b)
        return 0;
    if (!isfinite(x))
        return -1;
    *out = x;
    return 1;
}

const char *bsi_parse_double_says(int ok)
{
    return ok == -2 ? "%s longer than 400 characters"
           : ok == -1 ? "%s out of range for a double"
                      : "expected %s (a finite decimal number)";
}

size_t bsi_format_double(double x, char *buf)
{
    const char *point = locale_point();
    size_t plen = strlen(point);
    char tmp[64];
    for (int prec = 15; prec <= 17; prec++) {
        int n = snprintf(tmp, sizeof tmp, "%.*g", prec, x);
        if (n <= 0 || (size_t)n >= sizeof tmp)
            continue;
        /* Copy with the locale's decimal point turned into '.'. */
        size_t o = 0;
        for (size_t k = 0; k < (size_t)n;) {
            if (plen > 0 && strncmp(tmp + k, point, plen) == 0) {
                buf[o++] = '.';
                k += plen;
            } else {
                buf[o++] = tmp[k++];
            }
        }
        buf[o] = '\0';
        double back;
        /* bits, not values: -0.0 must come back as -0.0 */
        if (prec == 17 || (bsi_parse_double(buf, o, &back) == 1 && memcmp(&back, &x, sizeof x) == 0)) // NOLINT(bugprone-suspicious-memory-comparison,cert-exp42-c,cert-flp37-c)
            return o;
    }
    return 0; /* not reached for finite x */
}
