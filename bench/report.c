/* SPDX-License-Identifier: Apache-2.0 */
/*
 * report.c - rtbench's output (bench.h): markdown to stdout and to
 * DIR/results.md, metrics to DIR/results.csv, the comparison with an
 * earlier results.csv (--baseline), and PNG plots through gnuplot.
 *
 * One report per process; the functions keep its state in this file.
 * Every report starts with the header STYLE.md sec. 5 asks of benchmark
 * results: machine, date, compiler, build type, commit and the exact
 * command line (without the directory part of argv[0]).  Nothing written
 * names a path of the machine: data files and plot scripts refer to each
 * other by bare file names and gnuplot runs inside DIR.
 *
 * results.csv: one "key,value,direction" line per metric, direction 1
 * when higher is better, 0 when lower is better, -1 when never flagged.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"

#define MAX_PLOTS 32
#define PATH_SIZE 4096

struct metric {
    char key[96];
    double value;
    int direction;
};

static struct {
    const struct bench_options *opts;
    FILE *md;
    struct metric *metrics;
    size_t metric_count, metric_capacity;
    char plot_names[MAX_PLOTS][32];
    int plot_count;
    int check_failures;
} rep;

static int join_path(char *out, size_t size, const char *dir, const char *name)
{
    int n = snprintf(out, size, "%s/%s", dir, name);
    return n < 0 || (size_t)n >= size ? -1 : 0;
}

/* mkdir -p. */
static int make_dirs(const char *dir)
{
    char path[PATH_SIZE];
    if (snprintf(path, sizeof(path), "%s", dir) >= (int)sizeof(path))
        return -1;
    for (char *p = path + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(path, 0777) != 0 && errno != EEXIST)
            return -1;
        *p = '/';
    }
    if (mkdir(path, 0777) != 0 && errno != EEXIST)
        return -1;
    return 0;
}

static void emit(const char *text)
{
    fputs(text, stdout);
    if (rep.md)
        fputs(text, rep.md);
}

void report_printf(const char *fmt, ...)
{
    char buf[8192];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof(buf), fmt, ap);
    va_end(ap);
    emit(buf);
}

static void emit_cells(const char *cells)
{
    char line[8192];
    size_t n = 0;
    line[n++] = '|';
    line[n++] = ' ';
    for (const char *c = cells; *c && n + 8 < sizeof(line); c++) {
        if (*c == '|') {
            memcpy(&line[n], " | ", 3);
            n += 3;
        } else {
            line[n++] = *c;
        }
    }
    memcpy(&line[n], " |\n", 4);
    emit(line);
}

void report_row(const char *fmt, ...)
{
    char buf[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof(buf), fmt, ap);
    va_end(ap);
    emit_cells(buf);
}

void report_table_header(const char *cells)
{
    char sep[1024];
    size_t n = 0;
    emit_cells(cells);
    sep[n++] = '|';
    for (const char *c = cells; n + 6 < sizeof(sep); c++) {
        if (*c == '|' || *c == '\0') {
            memcpy(&sep[n], "---|", 4);
            n += 4;
        }
        if (*c == '\0')
            break;
    }
    sep[n++] = '\n';
    sep[n] = '\0';
    emit(sep);
}

void report_progress(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fflush(stderr);
}

void report_check_failed(void)
{
    rep.check_failures++;
}

int report_check_failures(void)
{
    return rep.check_failures;
}

void report_metric(const char *key, double value, int higher_is_better)
{
    if (rep.metric_count == rep.metric_capacity) {
        size_t cap = rep.metric_capacity ? 2 * rep.metric_capacity : 64;
        struct metric *m = realloc(rep.metrics, cap * sizeof(*m));
        if (!m)
            return; /* a lost metric only shortens results.csv */
        rep.metrics = m;
        rep.metric_capacity = cap;
    }
    struct metric *m = &rep.metrics[rep.metric_count++];
    snprintf(m->key, sizeof(m->key), "%s", key);
    m->value = value;
    m->direction = higher_is_better;
}

FILE *report_data_file(const char *name)
{
    char path[PATH_SIZE];
    if (!rep.opts || !rep.opts->out_dir || join_path(path, sizeof(path), rep.opts->out_dir, name))
        return NULL;
    return fopen(path, "w");
}

void report_plot(const char *name, const char *script)
{
    char file[64], path[PATH_SIZE];
    if (!rep.opts || !rep.opts->out_dir || rep.plot_count == MAX_PLOTS)
        return;
    snprintf(file, sizeof(file), "%s.gp", name);
    if (join_path(path, sizeof(path), rep.opts->out_dir, file))
        return;
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    fputs(script, f);
    fclose(f);
    snprintf(rep.plot_names[rep.plot_count++], sizeof(rep.plot_names[0]), "%s", name);
}

/* Appends with snprintf semantics; *len never passes size - 1. */
static void append(char *buf, size_t size, int *len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static void append(char *buf, size_t size, int *len, const char *fmt, ...)
{
    if ((size_t)*len + 1 >= size)
        return;
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf + *len, size - (size_t)*len, fmt, ap);
    va_end(ap);
    if (n > 0)
        *len = (size_t)*len + (size_t)n < size ? *len + n : (int)size - 1;
}

void report_strategy_plots(const char *name, const char *data_file, const char *time_title,
                           const char *sah_title, int count, const char *const *labels,
                           const int *has_sah)
{
    char script[4096], plot[64];
    for (int sah = 0; sah < 2; sah++) {
        const char *kind = sah ? "sah" : "time";
        int len = 0, first = 1;
        append(script, sizeof(script), &len,
               "set terminal pngcairo noenhanced size 800,480 font ',10'\n"
               "set output '%s_%s.png'\n"
               "set title '%s'\n"
               "set xlabel 'frame'\nset ylabel '%s'\n"
               "set logscale y\nset grid\nset key outside right\n",
               name, kind, sah ? sah_title : time_title,
               sah ? "SAH cost ratio (log)" : "ms per frame (log)");
        for (int k = 0; k < count; k++) {
            if (sah && !has_sah[k])
                continue;
            append(script, sizeof(script), &len, "%s'%s' using 1:%d with lines lw 2 title '%s'",
                   first ? "plot " : ", \\\n     ", data_file, (sah ? 3 : 2) + 2 * k, labels[k]);
            first = 0;
        }
        append(script, sizeof(script), &len, "\n");
        snprintf(plot, sizeof(plot), "%s_%s", name, kind);
        report_plot(plot, script);
    }
}

int report_open(const struct bench_options *opts)
{
    char path[PATH_SIZE];
    char cpu[256], date[64], compiler[256], commit[64], command[2048];
    memset(&rep, 0, sizeof(rep));
    rep.opts = opts;
    if (opts->out_dir) {
        if (make_dirs(opts->out_dir) ||
            join_path(path, sizeof(path), opts->out_dir, "results.md") ||
            !(rep.md = fopen(path, "w"))) {
            fprintf(stderr, "rtbench: cannot write results.md in --out directory '%s'\n",
                    opts->out_dir);
            return -1;
        }
    }
    sysinfo_cpu(cpu, sizeof(cpu));
    sysinfo_date(date, sizeof(date));
    sysinfo_compiler(compiler, sizeof(compiler));
    sysinfo_commit(commit, sizeof(commit));
    sysinfo_command(command, sizeof(command), opts->argc, opts->argv);

    report_printf("# rtbench results\n\n");
    if (opts->quick)
        report_printf("**--quick: smoke-test sizes and runs. These numbers are not results.**\n\n");
    report_table_header("|");
    report_row("machine|%s, %d cores online", cpu, sysinfo_cores());
    report_row("load average at start|%s", sysinfo_loadavg());
    report_row("date|%s", date);
    report_row("compiler|%s", compiler);
    report_row("build type|%s", RT_BENCH_BUILD_TYPE[0] ? RT_BENCH_BUILD_TYPE : "(none)");
    report_row("commit|%s", commit);
#ifdef RT_HAVE_EMBREE
    report_row("Embree|%s", bench_embree_version());
#else
    report_row("Embree|not built with Embree (RT_HAVE_EMBREE off)");
#endif
    report_row("traversal ISA (ours)|%s%s", bench_kernels()->name,
               opts->isa ? " (--isa)" : " (the best this CPU runs)");
    report_row("timings|median of %d run%s", opts->runs, opts->runs == 1 ? "" : "s");
    report_row("command|`%s`", command);
    return 0;
}

/* Reads an earlier results.csv and reports every metric that moved the
 * wrong way by more than the tolerance.  Returns the number flagged. */
static int compare_baseline(void)
{
    const struct bench_options *o = rep.opts;
    FILE *f = fopen(o->baseline, "r");
    if (!f) {
        report_printf("\nBaseline: cannot read --baseline file; no comparison.\n");
        return 0;
    }
    char line[256];
    int flagged = 0, compared = 0;
    report_printf("\n## Against the baseline\n\nTolerance %.1f%%; only metrics that got worse "
                  "by more than that are listed.\n\n",
                  o->tolerance);
    report_table_header("metric|baseline|now|change");
    while (fgets(line, sizeof(line), f)) {
        char key[96];
        double base;
        int direction;
        if (sscanf(line, "%95[^,],%lf,%d", key, &base, &direction) != 3 || direction < 0)
            continue;
        for (size_t i = 0; i < rep.metric_count; i++) {
            const struct metric *m = &rep.metrics[i];
            if (strcmp(m->key, key) != 0)
                continue;
            compared++;
            double change = base != 0.0 ? 100.0 * (m->value - base) / base : 0.0;
            int worse = direction ? change < -o->tolerance : change > o->tolerance;
            if (worse) {
                report_row("%s|%.4g|%.4g|%+.1f%% **worse**", key, base, m->value, change);
                flagged++;
            }
        }
    }
    fclose(f);
    report_printf("\n%d of %d compared metrics worse than the baseline by more than %.1f%%.\n",
                  flagged, compared, o->tolerance);
    return flagged;
}

static void write_csv(void)
{
    char path[PATH_SIZE];
    if (join_path(path, sizeof(path), rep.opts->out_dir, "results.csv"))
        return;
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    for (size_t i = 0; i < rep.metric_count; i++)
        fprintf(f, "%s,%.6g,%d\n", rep.metrics[i].key, rep.metrics[i].value,
                rep.metrics[i].direction);
    fclose(f);
}

/* Runs gnuplot inside DIR for each registered script. */
static void run_plots(void)
{
    const char *dir = rep.opts->out_dir;
    char quoted[PATH_SIZE];
    size_t n = 0;
    if (rep.plot_count == 0)
        return;
    if (!sysinfo_have_program("gnuplot")) {
        report_printf("\nPlots: skipped, gnuplot is not on PATH (the .gp scripts and .dat "
                      "files are in the output directory).\n");
        return;
    }
    /* Single-quote the directory for sh. */
    quoted[n++] = '\'';
    for (const char *c = dir; *c && n + 6 < sizeof(quoted); c++) {
        if (*c == '\'') {
            memcpy(&quoted[n], "'\\''", 4);
            n += 4;
        } else {
            quoted[n++] = *c;
        }
    }
    quoted[n++] = '\'';
    quoted[n] = '\0';
    report_printf("\nPlots:");
    for (int i = 0; i < rep.plot_count; i++) {
        char cmd[PATH_SIZE + 128];
        snprintf(cmd, sizeof(cmd), "cd %s && gnuplot %s.gp", quoted, rep.plot_names[i]);
        if (system(cmd) == 0)
            report_printf(" %s.png", rep.plot_names[i]);
        else
            report_printf(" (%s.png: gnuplot failed)", rep.plot_names[i]);
    }
    report_printf("\n");
}

int report_close(void)
{
    int flagged = 0;
    if (rep.opts && rep.opts->baseline)
        flagged = compare_baseline();
    if (rep.opts && rep.opts->out_dir) {
        write_csv();
        run_plots();
    } else {
        report_printf("\nPlots and results files: skipped (no --out DIR).\n");
    }
    if (rep.check_failures)
        report_printf("\n**%d correctness check(s) failed: paths that must agree did not (see "
                      "the warnings on stderr). Do not quote these numbers.**\n",
                      rep.check_failures);
    if (rep.md)
        fclose(rep.md);
    free(rep.metrics);
    int failures = rep.check_failures;
    memset(&rep, 0, sizeof(rep));
    rep.check_failures = failures;
    return flagged;
}
