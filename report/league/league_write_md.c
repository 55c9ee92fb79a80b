/* dv_league_write_md: league.md, the tables a paper could paste.
 *
 * Per target: objects down, engines across, a cell "0.0225 s/s (rk4, 8.2e-4 s)"
 * where reached, "— (what stops it)" where not; then each engine's summary at
 * that target; then the machine, the date, the versions, the cost cap and what
 * a cell claims. Every name and reason is literal Markdown text. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io_file.h"
#include "league.h"
#include "league_words.h"
#include "report_escape.h"

/* pre, s as literal Markdown text, post */
static void put_md(FILE *fp, const char *pre, const char *s, const char *post) {
  fputs(pre, fp);
  dv_report_escape_markdown(fp, s);
  fputs(post, fp);
}

/* the text of one cell of the matrix */
static void put_cell(FILE *fp, const dv_league_cell *c) {
  char cost[32], words[160];
  if (!c) {
    fputs(" |", fp);
    return;
  }
  if (c->outcome == DV_LEAGUE_REACHED) {
    dv_league_short_number(c->wall_per_sim_s, 3, cost, sizeof cost);
    dv_league_settings_words(c, words, sizeof words);
    fprintf(fp, " %s s/s", cost);
    if (words[0]) put_md(fp, " (", words, ")");
    fputs(" |", fp);
    return;
  }
  dv_league_short_why(c, words, sizeof words);
  fputs(" — (", fp);
  if (c->outcome != DV_LEAGUE_NOT_REACHED && c->why[0])
    fprintf(fp, "%s: ", dv_league_outcome_name(c->outcome));
  dv_report_escape_markdown(fp, words);
  fputs(") |", fp);
}

/* the matrix at target t */
static void put_matrix(FILE *fp, const dv_league *lg, double t) {
  fputs("| object |", fp);
  for (size_t e = 0; e < lg->nengines; e++)
    if (lg->engines[e].available) put_md(fp, " ", lg->engines[e].name, " |");
  fputs("\n|---|", fp);
  for (size_t e = 0; e < lg->nengines; e++)
    if (lg->engines[e].available) fputs("---|", fp);
  fputc('\n', fp);
  for (size_t o = 0; o < lg->nobjects; o++) {
    put_md(fp, "| ", lg->objects[o].name, " |");
    for (size_t e = 0; e < lg->nengines; e++)
      if (lg->engines[e].available)
        put_cell(fp, dv_league_cell_of(lg, lg->objects[o].name, lg->engines[e].name, t));
    fputc('\n', fp);
  }
}

/* the objects engine did not reach at t, and those it cannot model */
static void put_not_reached(FILE *fp, const dv_league *lg, const char *engine, double t) {
  const char *sep = "";
  for (int cannot = 0; cannot <= 1; cannot++) {
    const dv_league_outcome want = cannot ? DV_LEAGUE_CANNOT_MODEL : DV_LEAGUE_NOT_REACHED;
    const char *lead = cannot ? "cannot model: " : "";
    for (size_t o = 0; o < lg->nobjects; o++) {
      const dv_league_cell *c = dv_league_cell_of(lg, lg->objects[o].name, engine, t);
      if (!c || c->outcome != want) continue;
      fprintf(fp, "%s%s", sep, lead);
      dv_report_escape_markdown(fp, c->object);
      sep = ", ", lead = "";
    }
  }
  if (!*sep) fputs("none", fp);
}

/* each engine's standing at target t */
static void put_summary(FILE *fp, const dv_league *lg, double t) {
  fputs(
      "| engine | reached / run | cost, geometric mean (s/s) | steps / simulated s, geometric "
      "mean | not reached |\n|---|---|---|---|---|\n",
      fp);
  for (size_t e = 0; e < lg->nengines; e++) {
    const dv_league_engine *en = &lg->engines[e];
    dv_league_summary s;
    char cost[32], steps[32];
    if (!en->available) continue;
    dv_league_summarize(lg, en->name, t, &s);
    dv_league_short_number(s.geomean_wall_per_sim_s, 3, cost, sizeof cost);
    dv_league_short_number(s.geomean_steps_per_sim_s, 3, steps, sizeof steps);
    put_md(fp, "| ", en->name, " |");
    fprintf(fp, " %zu / %zu | %s | %s | ", s.reached, s.reached + s.not_reached,
            isnan(s.geomean_wall_per_sim_s) ? "—" : cost,
            isnan(s.geomean_steps_per_sim_s) ? "—" : steps);
    put_not_reached(fp, lg, en->name, t);
    fputs(" |\n", fp);
  }
}

/* the machine, the date, the versions, the cost cap and what a cell claims */
static void put_provenance(FILE *fp, const dv_league *lg) {
  char cap[32];
  dv_league_short_number(lg->cost_cap, 3, cap, sizeof cap);
  fputs("## How it was measured\n\n", fp);
  put_md(fp, "Machine: ", lg->machine, ". ");
  put_md(fp, "Date: ", lg->date, ". ");
  char version[64];
  snprintf(version, sizeof version, "diskval %s", lg->diskval_version);
  put_md(fp, "", version, ". Engines: ");
  for (size_t e = 0; e < lg->nengines; e++) {
    const dv_league_engine *en = &lg->engines[e];
    put_md(fp, e ? "; " : "", en->name, " ");
    dv_report_escape_markdown(fp, en->available ? en->version : "not available");
    if (!en->available && en->why[0]) put_md(fp, " (", en->why, ")");
  }
  fprintf(fp, ". Cost cap: %s s of wall per simulated s.", cap);
  for (size_t i = 0; i < lg->noverrides; i++) /* a claim re-runs with them too */
    put_md(fp, i ? " " : " Every cell ran with --set ", lg->overrides[i], i + 1 < lg->noverrides ? "," : ".");
  fputs("\n\n", fp);
  fputs(
      "A cell's settings are the cheapest that best's search finds meeting both its theta "
      "target and the matching path target (the scene's path limit scaled as its theta limit "
      "is), searched until a run would cost more than the cost cap or the error stops falling "
      "with the step; its numbers come from a compare at those settings with the targets as "
      "its limits, so re-running that compare (the cell's report) reproduces its claim; a "
      "cell is reached only when that compare passes, judged, within both targets. The search "
      "varies each engine's step and choice, and the targets set the theta limit: a --set of "
      "them is refused, so every --set listed above is one the cells ran with. "
      "Cost: wall seconds per simulated second of the engine's run.\n",
      fp);
  if (lg->interrupted)
    fputs("\nThe league was interrupted: the cells marked not run are missing.\n", fp);
}

int dv_league_write_md(const char *dir, const dv_league *lg, dv_error *err) {
  dv_io_file out;
  const int status = dv_io_open_in(&out, dir, "league.md", err);
  if (status) return status;
  FILE *fp = out.fp;
  fputs("# diskval league: every engine on the same objects, error against cost\n", fp);
  for (size_t t = 0; t < lg->ntargets; t++) {
    char target[32];
    dv_league_short_number(lg->targets[t], 3, target, sizeof target);
    fprintf(fp, "\n## theta within %s rad\n\n", target);
    put_matrix(fp, lg, lg->targets[t]);
    fprintf(fp, "\n### Per engine at %s rad\n\n", target);
    put_summary(fp, lg, lg->targets[t]);
  }
  fputc('\n', fp);
  put_provenance(fp, lg);
  return dv_io_commit(&out, err);
}
