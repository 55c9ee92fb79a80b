/* diskval_props: the properties of props.h over generated scenes; each
 * failure one line, then a tally per property (and for b, per metric).
 *
 *   diskval_props --seed S --count N [--first I] [--props gabcdetkn] [--plain]
 *                 [--known FILE]...
 *
 * FILE lists failures already reported, "P NAME" a line (tests/props_known.txt;
 * props/props_known.txt those of t, k, n): printed as "known", they do not
 * fail the run; any other failure does. --known may be given more than once.
 * --plain: the generator's scenes only, none drawn again (props_gen.c).
 * Exit 0 when no property failed, 1 when one did, 2 on bad arguments. CTest
 * runs each property on a fixed seed; ./run.sh bench runs 500 scenes and
 * prints each property's failures by the metric they name. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine_choose.h"
#include "props.h"

static const char *const NAMES[PROP_COUNT] = {
    "g (every generated scene loads as generated)",
    "a (the reference of the scene's body, solved again, agrees: state and pose form)",
    "b (an error 0.8x a limit past the shadow passes its metric, 1.25x fails it, named)",
    "c (no verdict changes under a rigid motion or a similarity scaling)",
    "d (no metric reads past the window, no pointwise verdict past its end)",
    "e (thickness 1e-9 r judges as the thin disk)",
    "t (a clock slowed 0.8x the boundary past the shadow passes, 1.25x fails)",
    "k (energy bled to 0.8x the drift limit passes, 1.25x fails)",
    "n (the reference from a start nudged 1e-6 to 1e-4 passes)"};

int props_known(const props_tally *t, char p, const char *scene) {
  char key[80];
  snprintf(key, sizeof key, "%c %s", p, scene);
  for (size_t i = 0; i < t->nknown; i++)
    if (!strcmp(t->known_list[i], key)) return 1;
  return 0;
}

/* the known failures of file into t: "P NAME" a line, '#' comments */
static int read_known(const char *path, props_tally *t) {
  FILE *fp = fopen(path, "r");
  if (!fp) return -1;
  char line[256];
  while (fgets(line, sizeof line, fp)) {
    line[strcspn(line, "#\r\n")] = 0;
    size_t n = strlen(line);
    while (n && line[n - 1] == ' ') line[--n] = 0;
    if (!n) continue;
    char(*grown)[80] = realloc(t->known_list, (t->nknown + 1) * sizeof *grown);
    if (!grown) return fclose(fp), -1;
    t->known_list = grown;
    snprintf(t->known_list[t->nknown++], 80, "%.79s", line);
  }
  return fclose(fp), 0;
}

static int usage(const char *what) {
  fprintf(stderr,
          "diskval_props: %s (usage: diskval_props --seed S --count N [--first I] "
          "[--props %s] [--plain] [--known FILE]...)\n",
          what, PROPS_LETTERS);
  return 2;
}

/* a whole number in [0, hi] */
static int number(const char *s, unsigned long long hi, unsigned long long *out) {
  char *end;
  if (!s || !*s || *s == '-') return -1;
  *out = strtoull(s, &end, 10);
  return *end || *out > hi ? -1 : 0;
}

int main(int argc, char **argv) {
  unsigned long long seed = 0, count = 0, first = 0;
  int have_seed = 0, plain = 0;
  const char *known[4];
  size_t nknown = 0;
  unsigned which = 0;
  for (int i = 1; i < argc; i++) {
    const char *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(argv[i], "--seed") && !number(v, 1ull << 62, &seed))
      have_seed = 1, i++;
    else if (!strcmp(argv[i], "--count") && !number(v, 1000000, &count))
      i++;
    else if (!strcmp(argv[i], "--known") && v && nknown < sizeof known / sizeof known[0])
      known[nknown++] = v, i++;
    else if (!strcmp(argv[i], "--first") && !number(v, 1ull << 40, &first))
      i++;
    else if (!strcmp(argv[i], "--plain"))
      plain = 1;
    else if (!strcmp(argv[i], "--props") && v && *v && strspn(v, PROPS_LETTERS) == strlen(v)) {
      for (const char *p = v; *p; p++) which |= 1u << (strchr(PROPS_LETTERS, *p) - PROPS_LETTERS);
      i++;
    } else
      return usage(argv[i]);
  }
  if (!have_seed || !count) return usage("--seed and --count are required");
  if (!which) which = (1u << PROP_COUNT) - 1;
  gsl_set_error_handler_off();
  dv_engine_choose_only((const dv_engine_type *const[]){NULL}); /* no engine's settings probed */
  props_tally t;
  memset(&t, 0, sizeof t);
  for (size_t k = 0; k < nknown; k++)
    if (read_known(known[k], &t)) return free(t.known_list), usage("--known: cannot read the file");
  for (unsigned long long i = 0; i < count; i++) {
    props_scene(seed, (size_t)(first + i), which, plain, &t, stdout);
    fflush(stdout);
  }
  int bad = 0;
  printf("%llu scenes, seed %llu from %llu:", count, seed, first);
  for (int k = 0; k < PROPS_NKINDS; k++)
    if (t.kinds[k]) printf(" %ld %s", t.kinds[k], props_kind_names[k]);
  printf(
      "; %ld judged, %ld periodic over 8 nutation periods or more, %ld released near an "
      "unstable state (exponential amplification)\n",
      t.judged, t.periodic8, t.unstable);
  printf(
      "the judge against the rule computed here, largest gaps: limits %.2g of them, early "
      "window %.2g s, pointwise end %.2g s, unexcused values %.2g of the limit; %ld bent past "
      "a pointwise end\n",
      t.gap[PROPS_GAP_LIMIT], t.gap[PROPS_GAP_EARLY], t.gap[PROPS_GAP_END], t.gap[PROPS_GAP_AGREE],
      t.d_pointwise);
  for (int p = 0; p < PROP_COUNT; p++) {
    if (!(which & 1u << p)) continue;
    printf("%-88s %6ld checks %4ld failed %4ld known %4ld not judged\n", NAMES[p], t.checks[p],
           t.failures[p], t.known[p], t.skipped[p]);
    bad |= t.failures[p] > 0;
    for (int m = 0; m < DV_NMETRICS; m++)
      if (t.runs[p][m])
        printf("    %c %-22s %6ld brackets ends %4ld wrong\n", PROPS_LETTERS[p], dv_metric_names[m],
               t.runs[p][m], t.wrong[p][m]);
    for (int m = 0; m <= DV_NMETRICS; m++)
      if (t.failed_by[p][m])
        printf("    %c failures naming %-22s %4ld\n", PROPS_LETTERS[p],
               m < DV_NMETRICS ? dv_metric_names[m] : "no metric", t.failed_by[p][m]);
  }
  free(t.known_list);
  return bad;
}
