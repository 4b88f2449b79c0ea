/* parse.c — strict number parsing for command lines and tables: the whole token must be
 * a finite number (inf only where the caller allows), and the failure says why. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "app.h"

void app_errf(char *err, const char *fmt, ...)
{
    if (!err)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, APP_ERR_LEN, fmt, ap);
    va_end(ap);
}

/* Copy s without surrounding blanks into buf (truncated to n - 1 chars). */
static const char *trimmed(const char *s, char *buf, size_t n)
{
    while (*s && isspace((unsigned char)*s))
        s++;
    size_t len = strlen(s);
    while (len > 0 && isspace((unsigned char)s[len - 1]))
        len--;
    if (len >= n)
        len = n - 1;
    memcpy(buf, s, len);
    buf[len] = '\0';
    return buf;
}

int app_parse_double(const char *s, int allow_inf, double *out, char *err)
{
    char tok[128];
    if (!s) {
        app_errf(err, "missing value");
        return -1;
    }
    trimmed(s, tok, sizeof tok);
    if (tok[0] == '\0') {
        app_errf(err, "empty value");
        return -1;
    }
    const char *t = tok[0] == '+' ? tok + 1 : tok;
    if (strcasecmp(t, "inf") == 0 || strcasecmp(t, "infinity") == 0) {
        if (!allow_inf) {
            app_errf(err, "'%s' is not finite (inf is not allowed here)", tok);
            return -1;
        }
        *out = INFINITY;
        return 0;
    }
    errno = 0;
    char *end;
    double v = strtod(tok, &end);
    if (end == tok || *end != '\0') {
        app_errf(err, "not a number: '%s'", tok);
        return -1;
    }
    if (!isfinite(v)) {
        app_errf(err, "'%s' is not finite", tok);
        return -1;
    }
    /* ERANGE with a finite result is underflow to a tiny or zero value: keep it. The
     * overflow case returned HUGE_VAL and was caught as not finite above. */
    *out = v;
    return 0;
}

const char *app_fmt(double x, char *buf)
{
    /* the shortest string among the precisions that read back exactly: "10", not "1e+01" */
    char best[APP_FMT_LEN] = "";
    for (int prec = 1; prec <= 17; prec++) {
        char s[APP_FMT_LEN];
        snprintf(s, sizeof s, "%.*g", prec, x);
        if ((!isfinite(x) || strtod(s, NULL) == x) && (!best[0] || strlen(s) < strlen(best)))
            memcpy(best, s, sizeof best);
    }
    memcpy(buf, best, APP_FMT_LEN);
    return buf;
}

int app_parse_long(const char *s, long lo, long hi, long *out, char *err)
{
    char tok[128];
    if (!s) {
        app_errf(err, "missing value");
        return -1;
    }
    trimmed(s, tok, sizeof tok);
    errno = 0;
    char *end;
    long v = strtol(tok, &end, 10);
    if (tok[0] == '\0' || end == tok || *end != '\0') {
        app_errf(err, "not an integer: '%s'", tok);
        return -1;
    }
    if (errno == ERANGE || v < lo || v > hi) {
        app_errf(err, "%s outside [%ld, %ld]", tok, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int app_parse_u64(const char *s, uint64_t *out, char *err)
{
    char tok[128];
    if (!s) {
        app_errf(err, "missing value");
        return -1;
    }
    trimmed(s, tok, sizeof tok);
    errno = 0;
    char *end;
    /* strtoull accepts a sign and wraps "-1"; a seed must be plain digits */
    unsigned long long v = strtoull(tok, &end, 10);
    if (!isdigit((unsigned char)tok[0]) || *end != '\0') {
        app_errf(err, "not a non-negative integer: '%s'", tok);
        return -1;
    }
    if (errno == ERANGE) {
        app_errf(err, "%s is larger than 2^64 - 1", tok);
        return -1;
    }
    *out = (uint64_t)v;
    return 0;
}

int app_parse_list(const char *s, double *out, int max, int *n, char *err)
{
    if (!s) {
        app_errf(err, "missing value");
        return -1;
    }
    int k = 0;
    const char *p = s;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        char tok[128];
        if (len >= sizeof tok)
            len = sizeof tok - 1;
        memcpy(tok, p, len);
        tok[len] = '\0';
        if (k == max) {
            app_errf(err, "more than %d components in '%s'", max, s);
            return -1;
        }
        char why[APP_ERR_LEN];
        if (app_parse_double(tok, 0, &out[k], why) != 0) {
            app_errf(err, "component %d: %s", k + 1, why);
            return -1;
        }
        k++;
        if (!comma)
            break;
        p = comma + 1;
    }
    *n = k;
    return 0;
}
