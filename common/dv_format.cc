// dv_format: the C interface to double-conversion's shortest and precision
// modes (the converter V8 uses), with the notation of printf's %g.
#include "dv_format.h"

#include <double-conversion/double-to-string.h>

#include <cmath>
#include <cstring>

using double_conversion::DoubleToStringConverter;
using double_conversion::StringBuilder;

namespace {

// shortest digits; plain decimals for 1e-4 <= |v| < 1e17 as %g, "1e-5", "1e20" beyond
const DoubleToStringConverter shortest(DoubleToStringConverter::NO_FLAGS, "inf", "nan", 'e', -4, 17,
                                       0, 0);

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

}  // namespace

// shortest round-trip text; "nan" (of either sign), "inf", "-inf"
extern "C" size_t dv_format_double(double v, char *buf, size_t size) {
  return emit(buf, size, [v](StringBuilder *sb) { shortest.ToShortest(v, sb); });
}

// shortest round-trip text, null where JSON has no number
extern "C" size_t dv_format_json(double v, char *buf, size_t size) {
  if (!std::isfinite(v)) {
    return emit(buf, size, [](StringBuilder *sb) { sb->AddString("null"); });
  }
  return dv_format_double(v, buf, size);
}

// %.*g with digits clamped to 1..17, so that the text fits DV_FORMAT_SIZE
extern "C" size_t dv_format_precision(double v, int digits, char *buf, size_t size) {
  int p = digits < 1 ? 1 : digits > 17 ? 17 : digits;
  return emit(buf, size, [v, p](StringBuilder *sb) { precision.ToPrecision(v, p, sb); });
}
