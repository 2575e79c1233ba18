/* Feeds a recorded eyehand pattern stream to the reference LWPR library (Klanke and
 * Vijayakumar, v1.2.6) through its public API and prints, after every pattern, each
 * output's receptive-field count and the library's prediction at the next pattern's input.
 *
 * Usage: lwpr_reference_driver STREAM INIT_D W_GEN EVERY
 * STREAM is the output of `cargo run --example lwpr_patterns`: a `bounds` line (low and
 * high of the five inputs), a `norm_out` line and one `p x0 .. x4 t0 t1 t2` line per
 * pattern. Inputs are normalised as eyehand normalises them, (x - low) / (high - low), and
 * handed to the library with norm_in 1; outputs use the library's own norm_out. Every other
 * setting is the library's default, which eyehand's defaults are.
 *
 * Output, one line per pattern: `n F0 F1 F2` with the field counts after the update and,
 * after every EVERY-th pattern but the last, ` Y0 Y1 Y2`: the predictions (degrees, cutoff
 * 0.001) at the next pattern's input, `-` where no trusted field is active there (the
 * library answers 0). Build: see tools/lwpr_reference.sh. */
#include <lwpr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define INPUTS 5
#define OUTPUTS 3
/* The library's confidence for a point no trusted field covers. */
#define UNCOVERED 1e19

typedef struct {
   double x[INPUTS];
   double t[OUTPUTS];
} Pattern;

static Pattern *read_stream(const char *file, double low[INPUTS], double span[INPUTS],
                            double *norm_out, int *count) {
   FILE *f = fopen(file, "r");
   char line[4096];
   int capacity = 1024, n = 0, i;
   Pattern *patterns = malloc(capacity * sizeof(Pattern));
   if (f == NULL || patterns == NULL) {
      fprintf(stderr, "%s: cannot read\n", file);
      exit(2);
   }
   while (fgets(line, sizeof line, f)) {
      if (strncmp(line, "bounds ", 7) == 0) {
         double b[2 * INPUTS];
         if (sscanf(line + 7, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", b, b + 1, b + 2,
                    b + 3, b + 4, b + 5, b + 6, b + 7, b + 8, b + 9) != 2 * INPUTS) {
            fprintf(stderr, "%s: bad bounds line\n", file);
            exit(2);
         }
         for (i = 0; i < INPUTS; i++) {
            low[i] = b[2 * i];
            span[i] = b[2 * i + 1] - b[2 * i];
         }
      } else if (strncmp(line, "norm_out ", 9) == 0) {
         *norm_out = atof(line + 9);
      } else if (strncmp(line, "p ", 2) == 0) {
         Pattern *p;
         if (n == capacity) {
            capacity *= 2;
            patterns = realloc(patterns, capacity * sizeof(Pattern));
         }
         p = &patterns[n++];
         if (sscanf(line + 2, "%lf %lf %lf %lf %lf %lf %lf %lf", p->x, p->x + 1, p->x + 2,
                    p->x + 3, p->x + 4, p->t, p->t + 1, p->t + 2) != INPUTS + OUTPUTS) {
            fprintf(stderr, "%s:%d: bad pattern line\n", file, n);
            exit(2);
         }
      }
   }
   fclose(f);
   *count = n;
   return patterns;
}

int main(int argc, char **argv) {
   LWPR_Model model;
   double low[INPUTS], span[INPUTS], norm_out = 1.0;
   double xn[INPUTS], y[OUTPUTS], conf[OUTPUTS];
   int count, every, k, i, d;
   Pattern *patterns;

   if (argc != 5 || (every = atoi(argv[4])) < 1) {
      fprintf(stderr, "usage: %s STREAM INIT_D W_GEN EVERY\n", argv[0]);
      return 2;
   }
   patterns = read_stream(argv[1], low, span, &norm_out, &count);
   if (!lwpr_init_model(&model, INPUTS, OUTPUTS, "eyehand")) return 1;
   lwpr_set_init_D_spherical(&model, atof(argv[2]));
   model.w_gen = atof(argv[3]);
   for (d = 0; d < OUTPUTS; d++) model.norm_out[d] = norm_out;

   for (k = 0; k < count; k++) {
      for (i = 0; i < INPUTS; i++) xn[i] = (patterns[k].x[i] - low[i]) / span[i];
      lwpr_update(&model, xn, patterns[k].t, NULL, NULL);
      printf("n %d %d %d", model.sub[0].numRFS, model.sub[1].numRFS, model.sub[2].numRFS);
      if (k + 1 < count && (k + 1) % every == 0) {
         for (i = 0; i < INPUTS; i++) xn[i] = (patterns[k + 1].x[i] - low[i]) / span[i];
         lwpr_predict(&model, xn, 0.001, y, conf, NULL);
         for (d = 0; d < OUTPUTS; d++) {
            if (conf[d] > UNCOVERED * norm_out) {
               printf(" -");
            } else {
               printf(" %.10e", y[d]);
            }
         }
      }
      printf("\n");
   }
   lwpr_free_model(&model);
   free(patterns);
   return 0;
}
