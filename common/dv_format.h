/* dv_format: doubles as the shortest decimal text that reads back exactly.
 *
 * Every number diskval writes goes through here: strtod of the text gives
 * back the same double, bit for bit, with the fewest significant digits that
 * do (0.3, not 0.29999999999999999). The notation is printf's %g choice:
 * plain decimals for 1e-4 <= |v| < 1e17 ("0.3", "12345678", "-0"), else an
 * exponent without padding or plus sign ("1e-05" is "1e-5", "1e+20" is
 * "1e20"). Non-finite values are written as the format needs: "nan", "inf"
 * and "-inf" in CSV (strtod reads them), null in JSON.
 *
 * The functions write at most size bytes including the terminating NUL (the
 * text is cut short if it does not fit) and return the length of the whole
 * text, as snprintf does; DV_FORMAT_SIZE bytes always suffice.
 */
#ifndef DV_FORMAT_H
#define DV_FORMAT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* bytes that hold any number these functions write, with its NUL */
#define DV_FORMAT_SIZE 32

/* the shortest text that strtod reads back to v; "nan", "inf", "-inf" */
size_t dv_format_double(double v, char *buf, size_t size);

/* as dv_format_double, but a JSON value: null for NaN and the infinities */
size_t dv_format_json(double v, char *buf, size_t size);

/* v rounded to digits significant digits (1 to 17), as printf's %.*g writes it
 * ("1e-05", "1e+20"), but for a v exactly halfway, rounded away from zero where
 * printf rounds to even; for numbers whose precision is a choice (times, timings) */
size_t dv_format_precision(double v, int digits, char *buf, size_t size);

#ifdef __cplusplus
}
#endif

#endif
