/* dv_league_write_csv: league.csv, a row per cell.
 *
 * Numbers are the shortest text that reads back exactly ("nan" where there is
 * none, as in diskval's other CSVs: steps too, for a cell that ran nothing);
 * text is quoted as RFC 4180 says where it holds a comma, a quote or a line
 * break (a quote doubled inside). */
#include <stdio.h>
#include <string.h>

#include "dv_format.h"
#include "io_file.h"
#include "league.h"
#include "league_words.h"

static const char header[] =
    "object,scenario_file,engine,engine_version,target,path_target,outcome,reached,choice_key,"
    "choice,step_key,step,theta_max_err,path_max_err,wall_per_sim_s,steps,order,verdict,why,"
    "cause,report\n";

/* ",TEXT", quoted where it needs to be */
static void put_text(FILE *fp, const char *text, int first) {
  if (!first) fputc(',', fp);
  if (!text[strcspn(text, ",\"\r\n")]) {
    fputs(text, fp);
    return;
  }
  fputc('"', fp);
  for (const char *p = text; *p; p++) {
    if (*p == '"') fputc('"', fp);
    fputc(*p, fp);
  }
  fputc('"', fp);
}

/* ",NUMBER" */
static void put_number(FILE *fp, double v) {
  char num[DV_FORMAT_SIZE];
  dv_format_double(v, num, sizeof num);
  fprintf(fp, ",%s", num);
}

static void put_row(FILE *fp, const dv_league_cell *c) {
  put_text(fp, c->object, 1);
  put_text(fp, c->scenario_file, 0);
  put_text(fp, c->engine, 0);
  put_text(fp, c->engine_version, 0);
  put_number(fp, c->target);
  put_number(fp, c->path_target);
  put_text(fp, dv_league_outcome_name(c->outcome), 0);
  fputs(c->outcome == DV_LEAGUE_REACHED ? ",true" : ",false", fp);
  put_text(fp, c->choice_key, 0);
  put_text(fp, c->choice, 0);
  put_text(fp, c->step_key, 0);
  put_number(fp, c->step);
  put_number(fp, c->theta_max_err);
  put_number(fp, c->path_max_err);
  put_number(fp, c->wall_per_sim_s);
  if (dv_league_cell_was_run(c) && c->steps >= 0)
    fprintf(fp, ",%ld", c->steps);
  else
    fputs(",nan", fp);
  put_number(fp, c->order);
  put_text(fp, c->verdict, 0);
  put_text(fp, c->why, 0);
  put_text(fp, c->cause, 0);
  put_text(fp, c->report, 0);
  fputc('\n', fp);
}

int dv_league_write_csv(const char *dir, const dv_league *lg, dv_error *err) {
  dv_io_file out;
  const int status = dv_io_open_in(&out, dir, "league.csv", err);
  if (status) return status;
  fputs(header, out.fp);
  for (size_t i = 0; i < lg->ncells; i++) put_row(out.fp, &lg->cells[i]);
  return dv_io_commit(&out, err);
}
