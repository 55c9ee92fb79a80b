/* scenario_number: the numbers a scenario value may be written as (not public API).
 *
 *   a number          strtod's whole text: 0.5, -2, 1e-3 (spaces around allowed)
 *   a multiple of pi  [NUMBER *] pi [/ NUMBER], or -pi [/ NUMBER]: pi/2, 2*pi, -pi/4,
 *                     0.5 * pi / 3 (spaces between the parts allowed)
 * and nothing else: no other names, operators or parentheses. The result must be
 * finite (NaN, inf, overflow and a division by zero are refused).
 */
#ifndef DV_SCENARIO_NUMBER_H
#define DV_SCENARIO_NUMBER_H

/* 0 with *out the value of text, or -1 when text is none of the above */
int dv_scenario_parse_number(const char *text, double *out);

#endif
