// dv_format: the C interface to Dragonbox's shortest digits and to
// double-conversion's precision mode (the converter V8 uses), with the
// notation of printf's %g.
#include "dv_format.h"

#include <double-conversion/double-to-string.h>
#include <dragonbox/dragonbox.h>

#include <cmath>
#include <cstdint>
#include <cstring>

using double_conversion::DoubleToStringConverter;
using double_conversion::StringBuilder;

namespace {

// printf's %.Ng: "1e-05", "1e+20", exponents from 1e-5 and from 10^N, no trailing zeros
const DoubleToStringConverter precision(DoubleToStringConverter::EMIT_POSITIVE_EXPONENT_SIGN |
                                            DoubleToStringConverter::NO_TRAILING_ZERO,
                                        "inf", "nan", 'e', -4, 17, 4, 0, 2);

// the text into buf, through a scratch buffer when buf may be too small; snprintf's return
template <typename Write>
size_t emit(char *buf, size_t size, Write write) {
  if (size >= DV_FORMAT_SIZE) {
    StringBuilder sb(buf, DV_FORMAT_SIZE);
    write(&sb);
    size_t n = static_cast<size_t>(sb.position());
    sb.Finalize();
    return n;
  }
  char scratch[DV_FORMAT_SIZE];
  StringBuilder sb(scratch, DV_FORMAT_SIZE);
  write(&sb);
  size_t n = static_cast<size_t>(sb.position());
  sb.Finalize();
  if (size) {
    size_t k = n < size - 1 ? n : size - 1;
    std::memcpy(buf, scratch, k);
    buf[k] = '\0';
  }
  return n;
}

// "00" ... "99": two digits a division, half the dependent divisions of one digit at a time
constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// the decimal digits of v (< 10^9) into the n bytes ending at end, n its digit count
void write_digits(std::uint32_t v, char *end) {
  while (v >= 100) {
    end -= 2;
    std::memcpy(end, kPairs + 2 * (v % 100), 2);
    v /= 100;
  }
  if (v >= 10)
    std::memcpy(end - 2, kPairs + 2 * v, 2);
  else
    end[-1] = static_cast<char>('0' + v);
}

// compared with powers of ten, not divided by ten: the divisions were a quarter of the digits' time
int digit_count(std::uint32_t v) {
  static constexpr std::uint32_t kPowers[] = {10,      100,      1000,      10000,     100000,
                                              1000000, 10000000, 100000000, 1000000000};
  int n = 1;
  while (n < 10 && v >= kPowers[n - 1]) n++;
  return n;
}

// the shortest digits of finite, nonzero |v| (Dragonbox, ties to even) into
// digits; their count, and the decimal exponent of the first digit in *exp10.
// A 17-digit significand is split at 10^8 into halves of 32-bit arithmetic.
int shortest_digits(double v, char digits[17], int *exp10) {
  namespace policy = jkj::dragonbox::policy;
  auto d = jkj::dragonbox::to_decimal(v, policy::sign::ignore, policy::trailing_zero::remove);
  const std::uint64_t sig = d.significand;
  int n;
  if (sig >= 100000000u) {
    const auto hi = static_cast<std::uint32_t>(sig / 100000000u);
    const auto lo = static_cast<std::uint32_t>(sig % 100000000u);
    const int nh = digit_count(hi);
    write_digits(hi, digits + nh);
    std::memset(digits + nh, '0', 8);  // lo's leading zeros
    write_digits(lo, digits + nh + 8);
    n = nh + 8;
  } else {
    n = digit_count(static_cast<std::uint32_t>(sig));
    write_digits(static_cast<std::uint32_t>(sig), digits + n);
  }
  *exp10 = d.exponent + n - 1;
  return n;
}

// Copies of a fixed 17 bytes (the most digits) that the pointer then steps past
// part of: a copy of variable length is compiled to a slow rep movs. So the
// digits have kSlack bytes after them, and the text as many beyond its end.
constexpr int kMaxDigits = 17, kSlack = 24, kTextBytes = DV_FORMAT_SIZE + kSlack;

// the text of finite v into out (kTextBytes): plain decimals for
// 1e-4 <= |v| < 1e17, else d.ddde-N / d.dddeN
size_t write_shortest(double v, char *out) {
  char *p = out;
  if (std::signbit(v)) *p++ = '-';
  if (v == 0.0) {
    *p++ = '0';
    return static_cast<size_t>(p - out);
  }
  char digits[kMaxDigits + kSlack];
  int e;
  const int n = shortest_digits(v, digits, &e);
  if (e < -4 || e >= 17) {
    *p++ = digits[0];
    if (n > 1) {
      *p++ = '.';
      std::memcpy(p, digits + 1, kMaxDigits);
      p += n - 1;
    }
    *p++ = 'e';
    if (e < 0) *p++ = '-';
    char exp[4];
    int k = 0;
    for (int a = e < 0 ? -e : e; a || !k; a /= 10) exp[k++] = static_cast<char>('0' + a % 10);
    while (k) *p++ = exp[--k];
  } else if (e < 0) {  // 0.000ddd
    *p++ = '0';
    *p++ = '.';
    for (int i = -1; i > e; i--) *p++ = '0';
    std::memcpy(p, digits, kMaxDigits);
    p += n;
  } else if (e + 1 >= n) {  // ddd000
    std::memcpy(p, digits, kMaxDigits);
    p += n;
    for (int i = n; i <= e; i++) *p++ = '0';
  } else {  // dd.ddd
    std::memcpy(p, digits, kMaxDigits);
    p += e + 1;
    *p++ = '.';
    std::memcpy(p, digits + e + 1, kMaxDigits);
    p += n - e - 1;
  }
  return static_cast<size_t>(p - out);
}

}  // namespace

// shortest round-trip text; "nan" (of either sign), "inf", "-inf"
extern "C" size_t dv_format_double(double v, char *buf, size_t size) {
  char text[kTextBytes];
  size_t n;
  if (std::isnan(v)) {
    n = 3, std::memcpy(text, "nan", 3);
  } else if (std::isinf(v)) {
    n = v > 0 ? 3 : 4, std::memcpy(text, v > 0 ? "inf" : "-inf", n);
  } else {
    n = write_shortest(v, text);
  }
  if (size >= DV_FORMAT_SIZE) {  // room for all of it: one copy of fixed length
    std::memcpy(buf, text, DV_FORMAT_SIZE);
    buf[n] = '\0';
  } else if (size) {
    const size_t k = n < size - 1 ? n : size - 1;
    std::memcpy(buf, text, k);
    buf[k] = '\0';
  }
  return n;
}

// shortest round-trip text, null where JSON has no number
extern "C" size_t dv_format_json(double v, char *buf, size_t size) {
  if (!std::isfinite(v)) {
    return emit(buf, size, [](StringBuilder *sb) { sb->AddString("null"); });
  }
  return dv_format_double(v, buf, size);
}

// %.*g with digits clamped to 1..17, so that the text fits DV_FORMAT_SIZE.
// Where the shortest digits of v are no more than p and plain decimals, they
// are its p-digit rounding: v is within 2^-53 of them, a p-digit tie at least
// 10^-p / 2 away (so p <= kSureDigits), and %g writes them as the shortest does.
extern "C" size_t dv_format_precision(double v, int digits, char *buf, size_t size) {
  constexpr int kSureDigits = 15;
  int p = digits < 1 ? 1 : digits > 17 ? 17 : digits;
  if (p <= kSureDigits && std::isfinite(v) && size >= DV_FORMAT_SIZE) {
    char sure[kMaxDigits + kSlack];
    int e = 0, n = 0;
    if (v != 0.0) n = shortest_digits(v, sure, &e);
    if (n <= p && e >= -4 && e < p) return dv_format_double(v, buf, size);
  }
  return emit(buf, size, [v, p](StringBuilder *sb) { precision.ToPrecision(v, p, sb); });
}
