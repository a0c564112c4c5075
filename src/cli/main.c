/*
 * main.c: the raytrace command: options, then scene file -> parser -> Scene
 * -> renderer -> Image -> writer (PPM, PNG or PFM) -> output file. The only
 * module that prints or exits.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "accel/bvh.h"
#include "accel/light_buffer.h"
#include "base/error.h"
#include "base/file.h"
#include "base/hash.h"
#include "base/outfile.h"
#include "base/threads.h"
#include "cli/options.h"
#include "image/image.h"
#include "image/tile.h"
#include "image/writer.h"
#include "math/number.h"
#include "render/render.h"
#include "render/seed001.h"
#include "scene/scene.h"
#include "scene/scene_accel.h"
#include "scenefile/load.h"
#include "scenefile/save.h"

#define RAYTRACE_VERSION "0.2.0"

/* The temporary output file, for the signal handler to remove. */
static const char *volatile main_temp_path;

/* Set while a progress bar is on the terminal, for the handler to erase. */
static volatile sig_atomic_t main_bar_shown;

/* On SIGINT or SIGTERM: remove the temporary file, say so, exit 128 + sig. */
static void main_on_signal(int sig)
{
    static const char msg[] = "raytrace: interrupted\n", erase[] = "\r\033[K";
    const char *temp = main_temp_path;

    if (temp)
        unlink(temp);
    if ((main_bar_shown && write(STDERR_FILENO, erase, sizeof erase - 1) < 0) ||
        write(STDERR_FILENO, msg, sizeof msg - 1) < 0) {
        /* Nothing more can be done. */
    }
    _exit(128 + sig);
}

/* At any exit raytrace did not choose (the OpenMP runtime's fatal errors
 * call exit() from its threads): remove the temporary file. */
static void main_at_exit(void)
{
    const char *temp = main_temp_path;

    if (temp)
        unlink(temp);
}

/* Arranges, once, for SIGINT, SIGTERM and any exit to remove the
 * temporary output file and for the signals to say so. */
static void main_catch_signals(void)
{
    static int caught;
    struct sigaction sa;

    if (caught)
        return;
    caught = 1;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = main_on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    atexit(main_at_exit);
}

/*
 * Opens the output like outfile_open() and arranges for SIGINT and SIGTERM to
 * remove its temporary file. Signals are held while the file is created, so
 * none can strike between its creation and its registration; no other
 * thread exists yet, so the mask of this one is enough.
 */
static int main_open_output(OutFile *out, const char *path, Error *err)
{
    sigset_t set, old;
    int rc;

    main_catch_signals();
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigprocmask(SIG_BLOCK, &set, &old);
    rc = outfile_open(out, path, err);
    if (rc == 0 && out->temp[0])
        main_temp_path = out->temp;
    sigprocmask(SIG_SETMASK, &old, NULL);
    return rc;
}

/* Prints err as "raytrace: FILE:LINE:COL: error: MESSAGE", then the line at
 * fault with a caret under the column; errors without a position print as
 * "raytrace: FILE: error: MESSAGE". */
static void main_report(const Error *err)
{
    /* Messages quote user bytes: shown safely, as the file and excerpt are. */
    char message[4 * ERROR_MESSAGE_MAX];

    error_escape(message, sizeof message, err->message, strlen(err->message), 0, NULL);
    if (err->line <= 0) {
        fprintf(stderr, "raytrace: %s%serror: %s\n", err->file, err->file[0] ? ": " : "",
                message);
        return;
    }
    fprintf(stderr, "raytrace: %s:%d:%d: error: %s\n", err->file, err->line, err->column,
            message);
    fprintf(stderr, "%5d | %s\n      | ", err->line, err->excerpt);
    /* Pad with the line's own tabs so the caret lines up; UTF-8 continuation
     * bytes take no column. */
    for (int i = 0; i < err->caret && err->excerpt[i]; i++) {
        unsigned char ch = (unsigned char)err->excerpt[i];
        if (ch == '\t')
            fputc('\t', stderr);
        else if ((ch & 0xC0) != 0x80)
            fputc(' ', stderr);
    }
    for (int i = (int)strlen(err->excerpt); i < err->caret; i++)
        fputc(' ', stderr);
    fputs("^\n", stderr);
}

static int main_usage(const char *msg)
{
    char safe[1024];

    error_escape(safe, sizeof safe, msg, strlen(msg), 0, NULL);
    fprintf(stderr, "raytrace: %s\nTry 'raytrace --help'.\n", safe);
    return 2;
}

/* Says whether paths a and b name the same existing file. */
static int main_same_file(const char *a, const char *b)
{
    struct stat sa, sb;

    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

static double main_now(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* The progress bar's state: drawn on standard error, a few times a second. */
typedef struct {
    double start;     /* when rendering began */
    double last_draw; /* when the bar was last drawn */
    int drawn;        /* the bar is on screen */
} MainProgress;

/* Draws "  42% [#########...........] 1.2 s, 1.6 s left" at most 5 times a
 * second (RenderProgress). */
static void main_progress(void *ctx, int done, int total)
{
    MainProgress *p = ctx;
    double now = main_now(), elapsed = now - p->start, frac = (double)done / total;
    char bar[31];
    int filled = (int)(frac * 30);

    if (now - p->last_draw < 0.2 || done == total)
        return;
    p->last_draw = now;
    p->drawn = 1;
    main_bar_shown = 1;
    for (int i = 0; i < 30; i++)
        bar[i] = i < filled ? '#' : '.';
    bar[30] = '\0';
    fprintf(stderr, "\r%4.0f%% [%s] %.1f s, %.1f s left ", 100 * frac, bar, elapsed,
            frac > 0 ? elapsed * (1 - frac) / frac : 0.0);
}

/* Returns the process's peak resident memory in bytes (0 if unknown). */
static double main_peak_memory(void)
{
    struct rusage ru;

    /* Linux reports ru_maxrss in kilobytes. */
    return getrusage(RUSAGE_SELF, &ru) == 0 ? (double)ru.ru_maxrss * 1024 : 0;
}


/* Prints, for -v, light buffer lb (light_buffer.h), around `what`. */
static void main_buffer(const char *what, const LightBuffer *lb)
{
    char b[NUMBER_FORMAT_MAX];

    fprintf(stderr, "raytrace: light buffer of %s: 6 x %d x %d cells, %zu entries, %s\n", what,
            lb->res, lb->res, lb->entry_count, number_bytes(b, light_buffer_memory(lb)));
}

/* Prints, for -v, the light buffers the scene was given. */
static void main_buffers(const Scene *scene)
{
    char what[32];

    if (scene->eye_buffer)
        main_buffer("the eye", scene->eye_buffer);
    for (size_t i = 0; scene->light_buffers && i < scene->light_count; i++)
        if (scene->light_buffers[i].first) {
            snprintf(what, sizeof what, "light %zu", i + 1);
            main_buffer(what, &scene->light_buffers[i]);
        }
}

/* Returns how ropts samples pixels, for a summary: "4 samples per pixel",
 * or under --noise its level and bounds (the text is overwritten by the
 * next call). */
static const char *main_samples(const RenderOptions *ropts)
{
    static char text[96];

    if (ropts->noise.level > 0)
        snprintf(text, sizeof text, "--noise %g (%u to %u samples a pixel)", ropts->noise.level,
                 ropts->noise.min_spp, ropts->noise.max_spp);
    else
        snprintf(text, sizeof text, "%d sample%s per pixel", ropts->samples,
                 ropts->samples == 1 ? "" : "s");
    return text;
}

/* Prints the -v summary: size, threads, rays by kind, the model when it
 * is seed 001's, time, speed, peak memory. */
static void main_statistics(const Image *img, const RenderOptions *ropts, SceneModel model,
                            int threads, const RayCounts *c, double seconds)
{
    unsigned long long all = c->primary + c->shadow + c->reflection + c->refraction +
                             c->occlusion + c->gather;
    char indirect[96] = "";

    fprintf(stderr, "raytrace: %d x %d pixels, %s, %d thread%s\n", img->width, img->height,
            main_samples(ropts), threads, threads == 1 ? "" : "s");
    if (ropts->indirect.ao_samples > 0 || ropts->indirect.gi_samples > 0)
        snprintf(indirect, sizeof indirect, "%llu occlusion, %llu gathering, ", c->occlusion,
                 c->gather);
    fprintf(stderr,
            "raytrace: rays: %llu primary, %llu shadow, %llu reflection, %llu refraction, "
            "%s%llu in all\n",
            c->primary, c->shadow, c->reflection, c->refraction, indirect, all);
    if (model == SCENE_MODEL_SEED001)
        fprintf(stderr, "raytrace: seed 001's model: its program's light, occlusion and "
                        "gathering; gamma %g\n",
                SEED001_GAMMA);
    if (ropts->indirect.ao_samples > 0)
        fprintf(stderr, "raytrace: ambient occlusion: %d rays a point, distance %g\n",
                ropts->indirect.ao_samples, ropts->indirect.ao_distance);
    if (ropts->indirect.gi_samples > 0)
        fprintf(stderr, "raytrace: global illumination: %d rays a point, %d bounce%s\n",
                ropts->indirect.gi_samples, ropts->indirect.gi_bounces,
                ropts->indirect.gi_bounces == 1 ? "" : "s");
    if (ropts->cutoff > 0)
        fprintf(stderr,
                "raytrace: cut-off %g levels: %llu rays left out, %llu pixels refined\n",
                ropts->cutoff, c->cut, c->refined);
    fprintf(stderr, "raytrace: rendered in %.3f s: %.2f Mrays/s\n", seconds,
            seconds > 0 ? all / seconds / 1e6 : 0.0);
    fprintf(stderr, "raytrace: peak memory: %.1f MB\n", main_peak_memory() / 1e6);
}

/* Reads opts' scene into *scene, reporting any fault; returns 0, or 1 (the
 * exit status) with *scene empty. */
static int main_load(const Options *opts, Scene *scene)
{
    Error err;

    if (load_scene_file(opts->scene_path, (SceneFormat)opts->scene_format, opts->memory_limit,
                        scene, &err) == 0) {
        /* Textures read despite damage, as other readers read them. */
        for (size_t i = 0; !opts->quiet && i < scene->texture_count; i++)
            if (scene->textures[i].warning[0])
                fprintf(stderr, "raytrace: %s: warning: %s\n", scene->textures[i].path,
                        scene->textures[i].warning);
        return 0;
    }
    main_report(&err);
    return 1;
}

/* Says, in *err, why path may not be written from opts' scene: it is the
 * scene file itself; returns 0 when it may. */
static int main_check_target(const Options *opts, const char *path, Error *err)
{
    if (strcmp(path, "-") != 0 && strcmp(opts->scene_path, "-") != 0 &&
        main_same_file(opts->scene_path, path)) {
        error_set(err, path, "the output is the scene file itself: refusing to overwrite it");
        return -1;
    }
    return 0;
}

/* Reads opts' scene, reports it and renders nothing; returns the exit status. */
static int main_check(const Options *opts)
{
    Scene scene;

    if (main_load(opts, &scene) != 0)
        return 1;
    if (!opts->quiet)
        printf("%s: OK: %d x %d pixels, %zu object%s, %zu light%s\n",
               strcmp(opts->scene_path, "-") == 0 ? "<stdin>" : opts->scene_path,
               scene.camera.width, scene.camera.height, scene_object_count(&scene),
               scene_object_count(&scene) == 1 ? "" : "s", scene.light_count,
               scene.light_count == 1 ? "" : "s");
    scene_free(&scene);
    return 0;
}

/* Reads opts' scene and writes it to opts' save path in the keyword format;
 * returns the exit status. */
static int main_save(const Options *opts)
{
    Scene scene;
    OutFile out;
    Error err;
    int rc;

    if (main_load(opts, &scene) != 0)
        return 1;
    if (main_check_target(opts, opts->save_path, &err) != 0 ||
        main_open_output(&out, opts->save_path, &err) != 0)
        goto fail;
    rc = save_scene(out.fp, &scene, file_display_name(opts->scene_path), opts->save_path,
                      &err);
    if (rc != 0)
        outfile_abort(&out, &err);
    else
        rc = outfile_commit(&out, &err);
    main_temp_path = NULL;
    if (rc != 0)
        goto fail;
    scene_free(&scene);
    return 0;

fail:
    main_report(&err);
    scene_free(&scene);
    return 1;
}

/* Sets aside from the memory limit what the image and its writing need
 * (and `extra` bytes more),
 * failing when the scene leaves less; then builds the scene's bounding
 * volume hierarchy (unless opts say not to), failing when it would pass
 * the limit and warning when memory runs out for it. Returns 0, or -1 with
 * *err set. */
static int main_prepare(const Options *opts, const WriterOptions *wopts, size_t extra,
                        Scene *scene, Error *err)
{
    size_t need = writer_memory(wopts, scene->camera.width, scene->camera.height) + extra;
    char a[NUMBER_FORMAT_MAX], b[NUMBER_FORMAT_MAX], c[NUMBER_FORMAT_MAX];
    size_t n = scene_bounded_count(scene);
    int rc;

    if (scene_set_aside(scene, need) != 0) {
        error_set(err, opts->scene_path,
                  "a %d x %d image needs %s to render and write: with the scene's %s, "
                  "more than the memory limit of %s (raise it with --memory-limit)",
                  scene->camera.width, scene->camera.height, number_bytes(a, need),
                  number_bytes(b, scene_memory(scene)), number_bytes(c, scene->memory_limit));
        return -1;
    }
    rc = opts->no_accel ? 0 : scene_build_accel(scene, opts->threads);
    if (rc == SCENE_OVER_LIMIT) {
        error_set(err, opts->scene_path,
                  "the bounding volume hierarchy of %zu objects needs up to %s, more than "
                  "the %s the memory limit leaves (--memory-limit; --no-accel renders "
                  "without it, slowly)",
                  n, number_bytes(a, bvh_build_memory(n)), number_bytes(b, scene_memory_left(scene)));
        return -1;
    }
    if (rc != 0)
        fprintf(stderr, "raytrace: warning: not enough memory for the bounding volume "
                        "hierarchy: every ray will test every object\n");
    return 0;
}

/* Allocates *img for scene's camera, keeping its linear colours for PFM;
 * returns 0, or -1 with *err set (and *img empty). */
static int main_image(const Options *opts, const WriterOptions *wopts, const Scene *scene,
                      int rows, Image *img, Error *err)
{
    int w = scene->camera.width, h = rows;

    if (image_init(img, w, h) == 0 && (wopts->format != FORMAT_PFM || image_keep_linear(img) == 0))
        return 0;
    error_set(err, opts->scene_path, "out of memory: a %d x %d image needs %zu bytes%s", w, h,
              image_size(w, h), wopts->format == FORMAT_PFM ? ", and 4 times that for PFM" : "");
    image_free(img);
    return -1;
}

/* Renders scene into img as ropts say, with the progress bar on a
 * terminal; stores the rays cast in *counts and returns the threads used. */
static int main_trace(const Options *opts, RenderOptions *ropts, const Scene *scene, Image *img,
                      RayCounts *counts, double *seconds)
{
    MainProgress progress = {0, 0, 0};
    double start = main_now();
    int threads;

    if (isatty(STDERR_FILENO) && !opts->quiet) {
        ropts->progress = main_progress;
        ropts->progress_ctx = &progress;
    }
    progress.start = progress.last_draw = start;
    threads = render(scene, ropts, img, counts);
    *seconds = main_now() - start;
    if (progress.drawn) {
        fputs("\r\033[K", stderr); /* erase the bar */
        main_bar_shown = 0;
    }
    ropts->progress = NULL;
    return threads;
}

/* Sets *in from the command line, else from the scene, else from its
 * model's defaults: the rays, the occlusion distance (the scene file's
 * units, as the scene may have been enlarged; by default a tenth of the
 * scene's size, seed 001's 2) and the bounces. */
static void main_indirect(const Options *opts, const Scene *scene, Indirect *in)
{
    int seed = scene->model == SCENE_MODEL_SEED001;
    double d = opts->ao_distance > 0 ? opts->ao_distance : scene->ao_distance;

    if (!(d > 0) && seed)
        d = SEED001_AO_DISTANCE;
    in->ao_samples = opts->ao >= 0               ? opts->ao
                     : scene->ao_samples >= 0 ? scene->ao_samples
                     : seed                   ? SEED001_AO_RAYS
                                              : 0;
    in->ao_distance = d > 0 ? ldexp(d, scene->length_exponent) : scene_size(scene) / 10;
    in->gi_samples = opts->gi >= 0               ? opts->gi
                     : scene->gi_samples >= 0 ? scene->gi_samples
                     : seed                   ? SEED001_GI_RAYS
                                              : 0;
    in->gi_bounces = opts->gi_bounces > 0 ? opts->gi_bounces
                     : scene->gi_bounces > 0 ? scene->gi_bounces
                                             : 1;
}

/* Says whether the physical model gives scene any ambient light for
 * ambient occlusion to darken. */
static int main_has_ambient(const Scene *scene)
{
    return colour_max(scene->ambient) > 0 && (scene->has_ambient || scene->format != SCENE_COURSE);
}

/* Prints "raytrace: note: WHAT" on standard error, the one place that
 * says an option changes nothing here. */
static void main_note(const Options *opts, const char *what)
{
    if (!opts->quiet)
        fprintf(stderr, "raytrace: note: %s\n", what);
}

/* Sets ropts' adaptive sampling from the command line, else the scene
 * (noise.h); says when an option of it, or -s under it, changes nothing. */
static void main_noise(const Options *opts, const Scene *scene, RenderOptions *ropts)
{
    NoiseOptions *n = &ropts->noise;
    int most = opts->max_spp ? opts->max_spp : scene->noise_max_spp;
    int least = opts->min_spp ? opts->min_spp : scene->noise_min_spp;

    n->level = opts->noise >= 0 ? opts->noise : scene->noise;
    n->max_spp = most ? (unsigned)most : NOISE_MAX_SPP;
    n->min_spp = least ? (unsigned)least : noise_default_min(n->level);
    /* A bound given alone moves the other's default out of its way. */
    if (n->min_spp > n->max_spp) {
        if (least)
            n->max_spp = n->min_spp;
        else
            n->min_spp = n->max_spp;
    }
    if (n->level > 0 && opts->samples)
        main_note(opts, "--spp changes nothing here: --noise takes as many samples a pixel as "
                        "its error needs (bounded by --min-spp and --max-spp)");
    if (n->level > 0)
        return;
    if (opts->min_spp || opts->max_spp)
        main_note(opts, "--min-spp and --max-spp change nothing without --noise: every pixel "
                        "takes the samples -s asks for");
    if (opts->spp_map)
        main_note(opts, "--spp-map writes nothing without --noise: every pixel takes the "
                        "samples -s asks for");
}

/* Applies the command line's choices about the picture to scene (its
 * model and size) and sets ropts' depth, samples and indirect light from
 * them; says once, on standard error, of each option given that can
 * change nothing in this scene. */
static void main_adjust(const Options *opts, Scene *scene, RenderOptions *ropts)
{
    int mpl = scene->format == SCENE_MPL, seed;

    if (opts->model >= 0 && !mpl)
        main_note(opts, "--model changes nothing here: it chooses how MPL scenes are lit; the "
                        "course and keyword formats have one model");
    else if (opts->model >= 0)
        scene->model = (SceneModel)opts->model;
    seed = scene->model == SCENE_MODEL_SEED001;
    if (opts->width > 0)
        camera_resize(&scene->camera, opts->width, opts->height);
    ropts->max_depth = opts->max_depth >= 0 ? opts->max_depth : seed ? SEED001_MAX_DEPTH : 10;
    ropts->samples = opts->samples ? opts->samples : scene->samples ? scene->samples : 1;
    ropts->no_shadows = opts->no_shadows;
    main_noise(opts, scene, ropts);
    main_indirect(opts, scene, &ropts->indirect);
    if (opts->ao > 0 && !seed && !main_has_ambient(scene))
        main_note(opts, "--ao changes nothing here: ambient occlusion darkens the ambient "
                        "light, and this scene has none (add one: the course's ambient:, the "
                        "MPL format's c Ambient)");
    if (opts->ao_distance > 0 && ropts->indirect.ao_samples == 0)
        main_note(opts, "--ao-distance changes nothing here: no ambient occlusion rays are cast "
                        "(--ao N)");
    if (opts->gi_bounces > 0 && seed && ropts->indirect.gi_samples > 0)
        main_note(opts, "--gi-bounces changes nothing here: seed 001's model gathers the colours "
                        "its rays meet, one bounce (--model physical gathers light)");
    else if (opts->gi_bounces > 0 && ropts->indirect.gi_samples == 0)
        main_note(opts, "--gi-bounces changes nothing here: no global illumination rays are "
                        "cast (--gi N)");
}

/* Returns the fingerprint of a render of scene with ropts: what it was read
 * from and every option that changes its pixels, so that tiles of
 * different renders are never merged. */
static uint64_t main_fingerprint(const Scene *scene, const RenderOptions *ropts)
{
    uint64_t h = hash_u64(HASH_START, scene->source_hash), distance;
    double d = ropts->indirect.ao_distance;

    memcpy(&distance, &d, sizeof distance);
    h = hash_u64(h, (uint64_t)ropts->max_depth);
    h = hash_u64(h, (uint64_t)ropts->samples);
    h = hash_u64(h, (uint64_t)ropts->indirect.ao_samples);
    h = hash_u64(h, ropts->indirect.ao_samples ? distance : 0);
    h = hash_u64(h, (uint64_t)ropts->indirect.gi_samples);
    h = hash_u64(h, (uint64_t)ropts->indirect.gi_bounces);
    h = hash_u64(h, (uint64_t)scene->model);
    h = hash_u64(h, (uint64_t)ropts->no_shadows);
    if (ropts->noise.level > 0) { /* else the hash of earlier versions */
        double level = ropts->noise.level;
        uint64_t bits;
        memcpy(&bits, &level, sizeof bits);
        h = hash_u64(h, bits);
        h = hash_u64(h, (uint64_t)ropts->noise.min_spp << 32 | ropts->noise.max_spp);
    }
    h = hash_u64(h, (uint64_t)scene->camera.width << 32 | (uint64_t)scene->camera.height);
    return hash_u64(h, sizeof(real)); /* a float build's pixels differ */
}

/* Makes *tile opts' tile of the scene's picture rendered with ropts;
 * returns 0, or -1 with *err when it would hold no row. */
static int main_tile(const Options *opts, const Scene *scene, const RenderOptions *ropts,
                     Tile *tile, Error *err)
{
    if (tile_make(tile, opts->tile_k, opts->tile_n, (TileLayout)opts->tile_layout,
                  scene->camera.width, scene->camera.height, main_fingerprint(scene, ropts)) == 0)
        return 0;
    error_set(err, opts->scene_path,
              "--tile %d/%d: the picture has %d rows, so at most %d tiles (each holds whole rows)",
              opts->tile_k, opts->tile_n, scene->camera.height, scene->camera.height);
    return -1;
}

/* Says, in *err, why opts' --spp-map may not be written: it is the
 * output itself; returns 0 when it may. */
static int main_spp_map_target(const Options *opts, Error *err)
{
    if (strcmp(opts->spp_map, "-") == 0 || strcmp(opts->spp_map, opts->output_path) == 0 ||
        (strcmp(opts->output_path, "-") != 0 && main_same_file(opts->output_path, opts->spp_map))) {
        error_set(err, opts->spp_map,
                  "--spp-map must name a file of its own, not the output or standard output");
        return -1;
    }
    return 0;
}

/* Returns the bytes main_noise_record() will take for scene's image. */
static size_t main_noise_memory(const Options *opts, const RenderOptions *ropts,
                                const Scene *scene)
{
    if (!(ropts->noise.level > 0) || !(opts->verbose || opts->spp_map))
        return 0;
    return (size_t)scene->camera.width * (size_t)scene->camera.height *
           (sizeof *ropts->spp + sizeof *ropts->error);
}

/* Gives ropts, under --noise, the arrays the samples and errors of img's
 * pixels are recorded in when -v or --spp-map will show them; returns 0,
 * or -1 when memory runs out. */
static int main_noise_record(const Options *opts, const Image *img, RenderOptions *ropts)
{
    size_t n = (size_t)img->width * (size_t)img->height;

    if (!(ropts->noise.level > 0) || !(opts->verbose || opts->spp_map))
        return 0;
    ropts->spp = malloc(n * sizeof *ropts->spp);
    ropts->error = malloc(n * sizeof *ropts->error);
    return ropts->spp && ropts->error ? 0 : -1;
}

/* Releases what main_noise_record() gave ropts. */
static void main_noise_free(RenderOptions *ropts)
{
    free(ropts->spp);
    free(ropts->error);
    ropts->spp = NULL;
    ropts->error = NULL;
}

/* Prints, for -v, the samples n pixels took under --noise and the errors
 * they reached. */
static void main_noise_statistics(const Options *opts, const RenderOptions *ropts, size_t n)
{
    NoiseSummary s;
    size_t short_of = 0;

    noise_summarise(ropts->spp, ropts->error, n, &s);
    for (size_t i = 0; i < n; i++)
        short_of += ropts->error[i] > ropts->noise.level;
    fprintf(stderr,
            "raytrace: --noise %g: samples a pixel %u to %u: mean %.1f, most %u; pixels by "
            "samples:",
            ropts->noise.level, ropts->noise.min_spp, ropts->noise.max_spp, s.mean_spp,
            s.max_spp);
    for (int b = 0; b < NOISE_BINS; b++)
        if (s.bins[b])
            fprintf(stderr, " %s%u %.1f%%", b == NOISE_BINS - 1 ? ">" : "<=",
                    b == NOISE_BINS - 1 ? 2u << b : 4u << b, 100.0 * s.bins[b] / n);
    fprintf(stderr, "\nraytrace: estimated error (one standard error, 68%% confidence): mean "
                    "%.3f, worst %.3f levels; %zu pixel%s short of %g at --max-spp\n",
            s.mean_error, s.worst_error, short_of, short_of == 1 ? "" : "s", ropts->noise.level);
    if (opts->spp_map)
        fprintf(stderr, "raytrace: map of samples: %s (black %u or fewer, white %u, log scale)\n",
                opts->spp_map, ropts->noise.min_spp, ropts->noise.max_spp);
}

/* Writes img to path as wopts say, replacing path only once the whole image
 * is written; returns 0, or -1 with *err set (and nothing left of a new
 * file). */
static int main_write(const char *path, const Image *img, const WriterOptions *wopts,
                      Error *err)
{
    OutFile out;

    if (main_open_output(&out, path, err) != 0)
        return -1;
    /* An interrupt from here on still finds main_temp_path: before the rename
     * it removes the unfinished file, after it the unlink finds nothing. */
    if (writer_write(out.fp, img, wopts) != 0) {
        error_set(err, path, "cannot write the image: %s", strerror(errno));
        outfile_abort(&out, err);
        main_temp_path = NULL;
        return -1;
    }
    if (outfile_commit(&out, err) != 0) {
        main_temp_path = NULL;
        return -1;
    }
    main_temp_path = NULL;
    return 0;
}

/* Writes opts' --spp-map: a width x height heat map of the samples ropts
 * recorded, in the format its name says; returns 0, or -1 with *err. */
static int main_spp_map(const Options *opts, const RenderOptions *ropts, int width, int height,
                        Error *err)
{
    WriterOptions w = {writer_format_for(opts->spp_map), 0, DEFLATE_FIXED, 95, 1, NULL};
    Image map;
    int rc;

    if (image_init(&map, width, height) != 0) {
        error_set(err, opts->spp_map, "out of memory for the map of samples");
        return -1;
    }
    noise_heat_map(ropts->spp, ropts->noise.min_spp, ropts->noise.max_spp, &map);
    rc = main_write(opts->spp_map, &map, &w, err);
    image_free(&map);
    return rc;
}

/* Renders opts' scene to opts' output; returns the exit status. */
static int main_render(const Options *opts)
{
    WriterOptions wopts = {(ImageFormat)opts->format, opts->ascii,
                           opts->png_stored ? DEFLATE_STORED : DEFLATE_FIXED, opts->jpeg_quality,
                           opts->jpeg_444, NULL};
    /* The linear colours of PFM would show what the cut-off leaves out. */
    RenderOptions ropts = {0, 1, wopts.format == FORMAT_PFM ? 0 : opts->cutoff,
                           opts->threads, NULL, NULL, {0, 0, 0, 0}, 0, 0, 0, {0, 0, 0}, NULL, NULL};
    RayCounts counts = {0};
    Tile tile;
    char record[TILE_RECORD_MAX];
    int rows;
    double start = main_now(), read_time, accel_time, render_time, write_time;
    Scene scene;
    Image img;
    Error err;
    int threads;

    if (main_load(opts, &scene) != 0)
        return 1;
    read_time = main_now() - start;
    main_adjust(opts, &scene, &ropts);
    if (strcmp(opts->output_path, "-") == 0 && isatty(STDOUT_FILENO)) {
        error_set(&err, "<stdout>", "refusing to write a binary image to a terminal");
        goto fail_scene;
    }
    /* An output that cannot be made is said before a long render. */
    if (main_check_target(opts, opts->output_path, &err) != 0 ||
        outfile_check(opts->output_path, &err) != 0 ||
        (ropts.noise.level > 0 && opts->spp_map &&
         (main_check_target(opts, opts->spp_map, &err) != 0 ||
          main_spp_map_target(opts, &err) != 0 || outfile_check(opts->spp_map, &err) != 0)) ||
        main_prepare(opts, &wopts, main_noise_memory(opts, &ropts, &scene), &scene, &err) != 0)
        goto fail_scene;
    accel_time = main_now() - start - read_time;
    rows = scene.camera.height;
    /* Gathered light has no bound the cut-off could use. */
    if (ropts.indirect.gi_samples > 0)
        ropts.cutoff = 0;
    if (opts->tile) {
        if (main_tile(opts, &scene, &ropts, &tile, &err) != 0)
            goto fail_scene;
        tile_record(&tile, record);
        wopts.note = record;
        ropts.row_first = tile.first;
        ropts.row_step = tile.step;
        rows = tile.count;
    }
    if (main_image(opts, &wopts, &scene, rows, &img, &err) != 0)
        goto fail_scene;
    if ((scene.model == SCENE_MODEL_SEED001 && image_encode_gamma(&img, SEED001_GAMMA) != 0) ||
        main_noise_record(opts, &img, &ropts) != 0) {
        error_set(&err, opts->scene_path, "out of memory");
        goto fail_image_only;
    }
    /* The render needs no file: the output is created once the picture is
     * done, so that nothing is left of it whatever ends the render. */
    main_catch_signals();
    threads = main_trace(opts, &ropts, &scene, &img, &counts, &render_time);
    write_time = main_now();
    if (main_write(opts->output_path, &img, &wopts, &err) != 0 ||
        (opts->spp_map && ropts.spp && main_spp_map(opts, &ropts, img.width, img.height, &err) != 0))
        goto fail_image;
    write_time = main_now() - write_time;
    if (opts->verbose) {
        fprintf(stderr, "raytrace: read the scene in %.3f s\n", read_time);
        if (scene.accel)
            fprintf(stderr, "raytrace: bounding volume hierarchy: %zu nodes, depth %d, built in "
                            "%.3f s%s\n",
                    scene.accel->node_count, scene.accel->depth, accel_time,
                    scene.accel->avx2 ? ", box tests in AVX2 and FMA" : "");
        main_buffers(&scene);
        main_statistics(&img, &ropts, scene.model, threads, &counts, render_time);
        if (ropts.spp)
            main_noise_statistics(opts, &ropts, (size_t)img.width * (size_t)img.height);
        fprintf(stderr, "raytrace: wrote the image in %.3f s\n", write_time);
    } else if (!opts->quiet && isatty(STDERR_FILENO)) {
        fprintf(stderr,
                "raytrace: wrote %s: %d x %d pixels, %zu object%s, %s, %.2f s, %d thread%s\n",
                strcmp(opts->output_path, "-") == 0 ? "<stdout>" : opts->output_path,
                img.width, img.height, scene_object_count(&scene),
                scene_object_count(&scene) == 1 ? "" : "s", main_samples(&ropts),
                main_now() - start, threads,
                threads == 1 ? "" : "s");
    }
    main_noise_free(&ropts);
    image_free(&img);
    scene_free(&scene);
    return 0;

fail_image:
    main_temp_path = NULL;
fail_image_only:
    main_noise_free(&ropts);
    image_free(&img);
fail_scene:
    main_report(&err);
    scene_free(&scene);
    return 1;
}

int main(int argc, char **argv)
{
    Options opts;
    char msg[256];

    OptionsAction action = options_parse(&opts, argc, argv, threads_processors(), msg,
                                         sizeof msg);

    if (action != OPTIONS_USAGE)
        threads_use(opts.threads); /* -j: reading, building and rendering */
    switch (action) {
    case OPTIONS_HELP:
        for (const char *const *part = options_help(); *part; part++)
            fputs(*part, stdout);
        return 0;
    case OPTIONS_VERSION:
#ifdef RAYTRACE_REAL_FLOAT
        puts("raytrace " RAYTRACE_VERSION " (geometry in single precision: make REAL=float)");
#else
        puts("raytrace " RAYTRACE_VERSION);
#endif
        return 0;
    case OPTIONS_USAGE:
        return main_usage(msg);
    case OPTIONS_CHECK:
        return main_check(&opts);
    case OPTIONS_SAVE:
        return main_save(&opts);
    case OPTIONS_RENDER:
        break;
    }
    return main_render(&opts);
}
