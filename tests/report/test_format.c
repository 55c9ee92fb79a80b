/* test_format: the numbers diskval writes read back exactly.
 *   - dv_format_double over a million random bit patterns (NaN excluded),
 *     uniform and log-uniform draws, integers up to 2^53 and special values
 *     (subnormals down to 4.9e-324, -0, 1e308, DBL_MAX, DBL_MIN, 0.1, 0.3,
 *     1/3): strtod reads the whole text back to the same bits, the text is no
 *     longer than %.17g's and has the fewest significant digits that do,
 *     the nearest to v of those (printf's correctly rounded digits);
 *   - the documented forms: "0.3", "1e-5", "12345678", "-0", "nan", "inf",
 *     "-inf", null in JSON; snprintf's return and truncation;
 *   - dv_format_precision as printf's %.*g; JSON items through cJSON;
 *   - trajectory rows (dv_run_csv_row) read back bit for bit, and the CSV of
 *     `diskval simulate SCENARIO --engine reduced --out -` parses field by field.
 * usage: test_format DISKVAL SCENARIO */
#define _DEFAULT_SOURCE /* open_memstream, popen */
#include <cjson/cJSON.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_format.h"
#include "dv_test.h"
#include "io_json.h"
#include "run_trajectory.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

/* xorshift64*: 64 random bits */
static uint64_t rng(void) {
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return rng_state * 0x2545f4914f6cdd1du;
}

/* uniform in [0, 1) */
static double uniform(void) {
  return (double)(rng() >> 11) * 0x1p-53;
}

/* the double with bit pattern b */
static double from_bits(uint64_t b) {
  double v;
  memcpy(&v, &b, sizeof v);
  return v;
}

/* the significant digits of a number's text: no sign, point, exponent, or outer zeros */
static int significant_digits(const char *s) {
  int n = 0, lead = 1, zeros = 0;
  for (; *s && *s != 'e'; s++) {
    if (*s < '0' || *s > '9') continue;
    if (*s == '0' && lead) continue;
    lead = 0;
    if (*s == '0') {
      zeros++;
    } else {
      n += zeros + 1;
      zeros = 0;
    }
  }
  return n;
}

/* the two texts have the same significant digits (ignoring trailing zeros) */
static int same_digits(const char *a, const char *b) {
  char da[32], db[32];
  int na = 0, nb = 0;
  for (; *a && *a != 'e' && na < 31; a++)
    if (*a >= '0' && *a <= '9' && (na || *a != '0')) da[na++] = *a;
  for (; *b && *b != 'e' && nb < 31; b++)
    if (*b >= '0' && *b <= '9' && (nb || *b != '0')) db[nb++] = *b;
  while (na && da[na - 1] == '0') na--;
  while (nb && db[nb - 1] == '0') nb--;
  return na == nb && !memcmp(da, db, (size_t)na);
}

static long checked, failed;

/* v formatted reads back to its bits, no longer than %.17g, with the fewest digits */
static void check_round_trip(double v) {
  char buf[DV_FORMAT_SIZE], ref[64], *end;
  size_t n = dv_format_double(v, buf, sizeof buf);
  double back = strtod(buf, &end);
  int len17 = snprintf(ref, sizeof ref, "%.17g", v);
  int ok = n == strlen(buf) && *end == '\0' && end != buf && !memcmp(&back, &v, sizeof v) &&
           (int)n <= len17;
  /* the nearest decimal with one digit fewer does not read back to v */
  int digits = significant_digits(buf);
  if (ok && digits > 1) {
    snprintf(ref, sizeof ref, "%.*e", digits - 2, v);
    double shorter = strtod(ref, NULL);
    ok = memcmp(&shorter, &v, sizeof v) != 0;
  }
  /* of the texts with that many digits, the nearest to v (printf's correctly
   * rounded one) wherever that one reads back */
  if (ok && isfinite(v) && v != 0.0) {
    snprintf(ref, sizeof ref, "%.*e", digits - 1, v);
    double nearest = strtod(ref, NULL);
    if (!memcmp(&nearest, &v, sizeof v)) ok = same_digits(buf, ref);
  }
  checked++;
  if (!ok && failed++ < 10) {
    snprintf(ref, sizeof ref, "%.17g", v);
    CHECK(0, "%s (%a) written as \"%s\" (%zu), read back as %.17g", ref, v, buf, n, back);
  }
}

/* the text dv_format_double writes for v is want */
static void check_text(double v, const char *want) {
  char buf[DV_FORMAT_SIZE];
  size_t n = dv_format_double(v, buf, sizeof buf);
  CHECK(!strcmp(buf, want) && n == strlen(want), "%.17g written as \"%s\", want \"%s\"", v, buf,
        want);
}

/* every kind of double through check_round_trip */
static void test_round_trip(void) {
  const double special[] = {0.0,
                            -0.0,
                            4.9e-324,
                            -4.9e-324,
                            2 * 4.9e-324,
                            DBL_MIN,
                            DBL_MIN - 4.9e-324,
                            nextafter(DBL_MIN, 1),
                            2.2250738585072009e-308,
                            1e-310,
                            DBL_MAX,
                            -DBL_MAX,
                            1e308,
                            -1e308,
                            1.7976931348623157e308,
                            DBL_EPSILON,
                            1 + DBL_EPSILON,
                            0.1,
                            0.2,
                            0.3,
                            0.1 + 0.2,
                            1.0 / 3,
                            2.0 / 3,
                            M_PI,
                            M_E,
                            1e-5,
                            1e-4,
                            9.9999999999999991e-5,
                            1e16,
                            1e17,
                            9.999999999999998e16,
                            1e21,
                            1e22,
                            1e23,
                            5e-324,
                            0x1p53,
                            0x1p53 - 1,
                            -0x1p53,
                            0x1p63,
                            123456789012345680.0};
  for (size_t i = 0; i < sizeof special / sizeof *special; i++) check_round_trip(special[i]);
  for (int i = 0; i < 1000000; i++) { /* random bits, NaN excluded */
    double v = from_bits(rng());
    if (!isnan(v)) check_round_trip(v);
  }
  for (int i = 0; i < 100000; i++) { /* subnormals */
    check_round_trip(from_bits(rng() & 0x800fffffffffffffu));
  }
  for (int i = 0; i < 200000; i++) { /* uniform in ranges */
    check_round_trip(uniform());
    check_round_trip(2e3 * uniform() - 1e3);
    check_round_trip(1e-3 * uniform());
    check_round_trip(pow(10, 600 * uniform() - 300)); /* log-uniform 1e-300 .. 1e300 */
  }
  for (int i = 0; i < 200000; i++) { /* integers up to 2^53, and small ones */
    check_round_trip((double)(rng() >> 11));
    check_round_trip((double)(int)(rng() % 2000001) - 1e6);
  }
  for (int k = -324; k <= 308; k++) check_round_trip(pow(10, k));
  for (int k = 0; k <= 53; k++) {
    check_round_trip(ldexp(1, k));
    check_round_trip(ldexp(1, k) - 1);
  }
  CHECK(failed == 0, "%ld of %ld numbers did not read back exactly or were not shortest", failed,
        checked);
  printf("round trip: %ld numbers, %ld failed\n", checked, failed);
}

/* the documented texts, JSON's null, snprintf's return and cut text */
static void test_texts(void) {
  check_text(0.3, "0.3");
  check_text(0.1 + 0.2, "0.30000000000000004");
  check_text(1.0 / 3, "0.3333333333333333");
  check_text(1e-5, "1e-5");
  check_text(1.5e-5, "1.5e-5");
  check_text(1e-4, "0.0001");
  check_text(12345678, "12345678");
  check_text(0x1p53, "9007199254740992");
  check_text(1e17, "1e17");
  check_text(1e20, "1e20");
  check_text(1e308, "1e308");
  check_text(DBL_MAX, "1.7976931348623157e308");
  check_text(4.9e-324, "5e-324");
  check_text(0.0, "0");
  check_text(-0.0, "-0");
  check_text(-2.5, "-2.5");
  check_text(NAN, "nan");
  check_text(-NAN, "nan");
  check_text(INFINITY, "inf");
  check_text(-INFINITY, "-inf");
  CHECK(strtod("inf", NULL) == INFINITY && strtod("-inf", NULL) == -INFINITY, "strtod of inf");
  CHECK(isnan(strtod("nan", NULL)), "strtod reads nan");

  const double json[] = {NAN, -NAN, INFINITY, -INFINITY};
  for (size_t i = 0; i < sizeof json / sizeof *json; i++) {
    char buf[DV_FORMAT_SIZE];
    dv_format_json(json[i], buf, sizeof buf);
    CHECK(!strcmp(buf, "null"), "JSON: %g written as \"%s\", want null", json[i], buf);
  }
  char buf[DV_FORMAT_SIZE];
  dv_format_json(-0.0, buf, sizeof buf);
  CHECK(!strcmp(buf, "-0"), "JSON: -0 written as \"%s\"", buf);

  char small[5] = "xxxx";
  size_t n = dv_format_double(0.1 + 0.2, small, sizeof small);
  CHECK(n == 19 && !strcmp(small, "0.30"), "cut short: \"%s\", length %zu", small, n);
  n = dv_format_double(0.3, small, 0);
  CHECK(n == 3 && !strcmp(small, "0.30"), "size 0 writes nothing, returns %zu", n);
  n = dv_format_json(NAN, small, 3);
  CHECK(n == 4 && !strcmp(small, "nu"), "JSON cut short: \"%s\"", small);
}

/* v lies exactly halfway between two numbers of digits significant digits */
static int exact_tie(double v, int digits) {
  static char text[1100]; /* every digit of a double: at most 767 significant ones */
  snprintf(text, sizeof text, "%.800e", fabs(v));
  char *mantissa = text, *e = strchr(text, 'e');
  int n = 0;
  for (char *p = mantissa; p < e; p++) {
    if (*p == '.') continue;
    if (n == digits && *p != '5') return 0;
    if (n > digits && *p != '0') return 0;
    n++;
  }
  return n > digits;
}

/* dv_format_precision writes what printf's %.*g writes, but for exact ties */
static void test_precision(void) {
  const int digits[] = {1, 6, 12, 17};
  long bad = 0, ties = 0;
  for (int i = 0; i < 300000; i++) {
    double v;
    switch (i % 3) {
      case 0:
        v = from_bits(rng());
        break;
      case 1:
        v = (i % 2 ? 1 : -1) * pow(10, 40 * uniform() - 20);
        break;
      default: /* times on a fine grid; short digits at every exponent */
        v = i % 2 ? 1e-4 * (double)(i / 3) : (double)(i % 997) * pow(10, i % 37 - 12);
        break;
    }
    if (isnan(v)) continue;
    for (size_t d = 0; d < sizeof digits / sizeof *digits; d++) {
      char got[DV_FORMAT_SIZE], want[64];
      size_t n = dv_format_precision(v, digits[d], got, sizeof got);
      snprintf(want, sizeof want, "%.*g", digits[d], v);
      if (strcmp(got, want) && exact_tie(v, digits[d]) &&
          fabsl(strtold(got, NULL)) > fabsl(strtold(want, NULL))) {
        ties++; /* printf rounds half to even, double-conversion away from zero */
        continue;
      }
      if ((strcmp(got, want) || n != strlen(want)) && bad++ < 10)
        CHECK(0, "%%.%dg of %a: \"%s\", printf \"%s\"", digits[d], v, got, want);
    }
  }
  CHECK(bad == 0, "%ld texts differ from printf's %%g", bad);
  printf("precision: %ld exact ties rounded away from zero\n", ties);
  char buf[DV_FORMAT_SIZE];
  dv_format_precision(NAN, 12, buf, sizeof buf);
  CHECK(!strcmp(buf, "nan"), "precision NaN: \"%s\"", buf);
  dv_format_precision(-INFINITY, 12, buf, sizeof buf);
  CHECK(!strcmp(buf, "-inf"), "precision -inf: \"%s\"", buf);
}

/* JSON items print exactly through cJSON, non-finite as null */
static void test_json(void) {
  cJSON *a = cJSON_CreateArray();
  const double fixed[] = {0.3, 0.1 + 0.2, NAN, INFINITY, -0.0, 1e-5};
  for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++)
    cJSON_AddItemToArray(a, dv_io_json_double(fixed[i]));
  char *text = cJSON_PrintUnformatted(a);
  CHECK(text && !strcmp(text, "[0.3,0.30000000000000004,null,null,-0,1e-5]"), "JSON: %s",
        text ? text : "(null)");
  free(text);
  cJSON_Delete(a);

  enum { N = 10000 };
  static double v[N];
  a = cJSON_CreateArray();
  for (int i = 0; i < N; i++) {
    do v[i] = from_bits(rng());
    while (!isfinite(v[i]));
    cJSON_AddItemToArray(a, dv_io_json_double(v[i]));
  }
  text = cJSON_PrintUnformatted(a);
  cJSON_Delete(a);
  cJSON *parsed = text ? cJSON_Parse(text) : NULL;
  CHECK(parsed && cJSON_GetArraySize(parsed) == N, "JSON of %d numbers parses", N);
  long bad = 0;
  const char *p = text ? text + 1 : "";
  for (int i = 0; i < N && text; i++) {
    char *end;
    double back = strtod(p, &end);
    if ((memcmp(&back, &v[i], sizeof back) || (*end != ',' && *end != ']')) && bad++ < 5)
      CHECK(0, "JSON number %d: %.17g read back as %.17g", i, v[i], back);
    p = end + 1;
  }
  CHECK(bad == 0, "%ld JSON numbers did not read back", bad);
  cJSON_Delete(parsed);
  free(text);
}

/* the fields of a CSV line (cut in place at the commas) that strtod reads whole */
static int parse_fields(char *line, double *v, int max) {
  int n = 0;
  for (char *f = strtok(line, ",\n"); f; f = strtok(NULL, ",\n")) {
    char *end;
    double x = strtod(f, &end);
    if (end == f || *end != '\0' || n == max) return -1;
    v[n++] = x;
  }
  return n;
}

/* rows of random samples read back bit for bit; t as %.12g */
static void test_rows(void) {
  char *buf = NULL;
  size_t len = 0;
  FILE *fp = open_memstream(&buf, &len);
  enum { ROWS = 20000 };
  static dv_sample s[ROWS];
  for (int i = 0; i < ROWS; i++) {
    memset(&s[i], 0, sizeof s[i]);
    s[i].t = 1e-4 * i;
    double *cols[] = {&s[i].y[RED_TH],  &s[i].y[RED_PH],  &s[i].y[RED_PS],  &s[i].y[RED_X],
                      &s[i].y[RED_Y],   &s[i].contact[0], &s[i].contact[1], &s[i].y[RED_VTH],
                      &s[i].y[RED_VPH], &s[i].y[RED_VPS], &s[i].energy};
    for (size_t c = 0; c < sizeof cols / sizeof *cols; c++) {
      *cols[c] = i % 4 ? (uniform() - 0.5) * pow(10, 8 * uniform() - 6) : from_bits(rng());
      if (isnan(*cols[c])) *cols[c] = i % 3 ? -0.0 : INFINITY;
    }
    dv_run_csv_row(fp, &s[i]);
  }
  fclose(fp);
  long bad = 0;
  char *line = buf;
  for (int i = 0; i < ROWS; i++) {
    char *nl = strchr(line, '\n');
    if (!nl) {
      CHECK(0, "row %d missing", i);
      break;
    }
    *nl = '\0';
    double v[12], t12;
    char t[64];
    snprintf(t, sizeof t, "%.12g", s[i].t);
    t12 = strtod(t, NULL);
    const double want[12] = {t12,
                             s[i].y[RED_TH],
                             s[i].y[RED_PH],
                             s[i].y[RED_PS],
                             s[i].y[RED_X],
                             s[i].y[RED_Y],
                             s[i].contact[0],
                             s[i].contact[1],
                             s[i].y[RED_VTH],
                             s[i].y[RED_VPH],
                             s[i].y[RED_VPS],
                             s[i].energy};
    int n = parse_fields(line, v, 12);
    if ((n != 12 || memcmp(v, want, sizeof want)) && bad++ < 5) CHECK(0, "row %d differs", i);
    line = nl + 1;
  }
  CHECK(bad == 0, "%ld of %d rows did not read back", bad, ROWS);
  free(buf);
}

/* diskval simulate's CSV: the header, then rows of 12 numbers strtod reads whole */
static void test_simulate(const char *diskval, const char *scenario) {
  char cmd[4096];
  snprintf(cmd, sizeof cmd, "'%s' simulate '%s' --engine reduced --out -", diskval, scenario);
  FILE *fp = popen(cmd, "r");
  CHECK(fp, "popen %s", cmd);
  if (!fp) return;
  char line[4096];
  long rows = 0, bad = 0;
  int header = fgets(line, sizeof line, fp) && !strcmp(line, DV_CSV_HEADER "\n");
  CHECK(header, "header: %s", line);
  while (fgets(line, sizeof line, fp)) {
    double v[12];
    char copy[4096];
    snprintf(copy, sizeof copy, "%s", line);
    if (parse_fields(line, v, 12) != 12 && bad++ < 5) CHECK(0, "row %ld: %s", rows + 1, copy);
    rows++;
  }
  int status = pclose(fp);
  CHECK(status == 0, "%s: exit status %d", cmd, status);
  CHECK(rows > 10 && bad == 0, "%ld rows, %ld bad", rows, bad);
  printf("simulate: %ld rows, %ld bad\n", rows, bad);
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: test_format DISKVAL SCENARIO\n");
    return 2;
  }
  test_round_trip();
  test_texts();
  test_precision();
  test_json();
  test_rows();
  test_simulate(argv[1], argv[2]);
  return TEST_RESULT();
}
