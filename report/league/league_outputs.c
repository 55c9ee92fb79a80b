/* league_outputs: the files a league writes into its folder, named and written. */
#include "league.h"
#include "league_words.h"

void dv_league_output_names(const dv_league *lg, char (*names)[96], const char **out) {
  static const char *const FIXED[] = {"league.html",  "league.json", "league.csv", "league.md",
                                      "overview.svg", "cells",       "compare"};
  size_t n = 0;
  for (size_t i = 0; i < sizeof FIXED / sizeof FIXED[0]; i++) out[n++] = FIXED[i];
  for (size_t o = 0; o < lg->nobjects; o++) {
    dv_league_figure_file(lg->objects[o].name, names[o], sizeof names[o]);
    out[n++] = names[o];
  }
  out[n] = NULL;
}

int dv_league_write_all(const char *dir, const dv_league *lg, dv_error *err) {
  return dv_league_write_json(dir, lg, err) || dv_league_write_csv(dir, lg, err) ||
         dv_league_write_md(dir, lg, err) || dv_league_write_html(dir, lg, err) ||
         dv_league_write_figures(dir, lg, err);
}
