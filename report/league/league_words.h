/* dv_league_words: a cell in a few characters, for the Markdown table and the page.
 *
 * Numbers are short (a table's cell is narrow): 3 significant digits for a
 * cost, 2 for a step, an exponent below 1e-2 or from 1e4 ("8.2e-4", "0.0225").
 */
#ifndef DV_LEAGUE_WORDS_H
#define DV_LEAGUE_WORDS_H

#include <stddef.h>

#include "league.h"

/* v with digits significant digits, as above; "nan", "inf" when not finite */
void dv_league_short_number(double v, int digits, char *buf, size_t size);

/* the cell's settings: "rk4, 8.2e-4 s" (a timestep), "cvode, rtol 1e-8" (any
 * other step key: its last word), without the choice when it has none */
void dv_league_settings_words(const dv_league_cell *c, char *buf, size_t size);

/* what stops the cell, short: its why up to the first ':', ';', '(' or ", ",
 * at most about 40 bytes (cut at a character's boundary, with "..."); the
 * outcome's name when it has no why */
void dv_league_short_why(const dv_league_cell *c, char *buf, size_t size);

/* the cell was run: its search and its compare (reached or not reached) */
int dv_league_cell_was_run(const dv_league_cell *c);

/* "work_precision_OBJECT.svg", each byte of the object's name outside
 * [A-Za-z0-9_.-] an '_' (a name is never a path) */
void dv_league_figure_file(const char *object, char *buf, size_t size);

#endif
