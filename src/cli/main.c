/*
 * main.c: the raytrace command: options, then scene file -> parser -> Scene
 * -> renderer -> Image -> writer (PPM, PNG or PFM) -> output file. The only
 * module that prints or exits.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh.h"
#include "base/error.h"
#include "base/file.h"
#include "base/interrupt.h"
#include "base/outfile.h"
#include "base/process.h"
#include "base/threads.h"
#include "cli/adjust.h"
#include "cli/options.h"
#include "cli/summary.h"
#include "image/image.h"
#include "image/tile.h"
#include "image/writer.h"
#include "math/number.h"
#include "render/irradiance.h"
#include "render/model.h"
#include "render/pass.h"
#include "render/render.h"
#include "scene/scene.h"
#include "scene/scene_accel.h"
#include "scene/scene_filter.h"
#include "scenefile/load.h"
#include "scenefile/save.h"

#define RAYTRACE_VERSION "0.2.0"

/*
 * Opens the output like outfile_open(), its temporary file watched from
 * before it exists (base/interrupt.h): an exit from within outfile_open()
 * (a failed allocation in the C library's stream, after the named
 * temporary is made) still finds it; until it is made, the name is
 * empty. Interrupts are held while the file is
 * created, so none can strike between its creation and its watch.
 */
static int main_open_output(OutFile *out, const char *path, Error *err)
{
    int rc;

    interrupt_hold();
    out->temp[0] = '\0';
    interrupt_watch(out->temp);
    rc = outfile_open(out, path, err);
    if (rc != 0 || !out->temp[0])
        interrupt_watch(NULL);
    interrupt_release();
    return rc;
}

/* Prints err as "raytrace: FILE:LINE:COL: KIND: MESSAGE" (KIND: "error" or
 * "warning"), then the line at fault with a caret under the column; errors
 * without a position print as "raytrace: FILE: KIND: MESSAGE". */
static void main_report(const Error *err, const char *kind)
{
    /* Messages quote user bytes: shown safely, as the file and excerpt are. */
    char message[4 * ERROR_MESSAGE_MAX];

    error_escape(message, sizeof message, err->message, strlen(err->message), 0, NULL);
    if (err->line <= 0) {
        fprintf(stderr, "raytrace: %s%s%s: %s\n", err->file, err->file[0] ? ": " : "", kind,
                message);
        return;
    }
    fprintf(stderr, "raytrace: %s:%d:%d: %s: %s\n", err->file, err->line, err->column, kind,
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
    double now = process_seconds(), elapsed = now - p->start, frac = (double)done / total;
    char bar[31];
    int filled = (int)(frac * 30);

    if (now - p->last_draw < 0.2 || done == total)
        return;
    p->last_draw = now;
    p->drawn = 1;
    interrupt_bar(1);
    for (int i = 0; i < 30; i++)
        bar[i] = i < filled ? '#' : '.';
    bar[30] = '\0';
    fprintf(stderr, "\r%4.0f%% [%s] %.1f s, %.1f s left ", 100 * frac, bar, elapsed,
            frac > 0 ? elapsed * (1 - frac) / frac : 0.0);
}

/* Reads opts' scene into *scene and *source, reporting any fault; returns
 * 0, or 1 (the exit status) with both empty. */
static int main_load(const Options *opts, Scene *scene, SceneSource *source)
{
    Error err;

    if (load_scene_file(opts->scene_path, (SceneFormat)opts->scene_format, opts->memory_limit,
                        opts->strict, scene, source, &err) == 0) {
        for (size_t i = 0; !opts->quiet && i < scene->warning_count; i++)
            main_report(&scene->warnings[i], "warning");
        if (!opts->quiet && scene->warnings_dropped > 0)
            fprintf(stderr, "raytrace: %s: warning: %zu more warnings of the same kinds\n",
                    file_display_name(opts->scene_path), scene->warnings_dropped);
        /* Textures read despite damage, as other readers read them. */
        for (size_t i = 0; !opts->quiet && i < scene->texture_count; i++)
            if (scene->textures[i].warning[0])
                fprintf(stderr, "raytrace: %s: warning: %s\n", scene->textures[i].path,
                        scene->textures[i].warning);
        return 0;
    }
    main_report(&err, "error");
    return 1;
}

/* Says, in *err, why path may not be written from opts' scene (read with
 * source): it is the scene file itself, or a file the scene reads (a
 * texture, a mesh), under any name or link; returns 0 when it may. */
static int main_check_target(const Options *opts, const Scene *scene, const SceneSource *source,
                             const char *path, Error *err)
{
    if (strcmp(path, "-") == 0)
        return 0;
    if (strcmp(opts->scene_path, "-") != 0 && file_same(opts->scene_path, path)) {
        error_set(err, path, "the output is the scene file itself: refusing to overwrite it");
        return -1;
    }
    for (size_t i = 0; i < scene->texture_count; i++)
        if (file_same(scene->textures[i].path, path)) {
            error_set(err, path, "the output is the scene's texture '%s': refusing to "
                      "overwrite it", scene->textures[i].path);
            return -1;
        }
    for (size_t i = 0; i < source->mesh_count; i++) {
        const SceneMesh *m = &source->meshes[i];
        if (file_same(m->opened, path)) {
            error_set(err, path, "the output is the scene's mesh '%s': refusing to overwrite it",
                      m->opened);
            return -1;
        }
        for (size_t k = 0; k < m->library_count; k++)
            if (file_same(m->libraries[k], path)) {
                error_set(err, path, "the output is the material library '%s' of the scene's "
                          "mesh: refusing to overwrite it", m->libraries[k]);
                return -1;
            }
    }
    return 0;
}

/* Reads opts' scene, reports it and renders nothing; returns the exit status. */
static int main_check(const Options *opts)
{
    SceneSource source;
    Scene scene;

    if (main_load(opts, &scene, &source) != 0)
        return 1;
    source_free(&source);
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
    SceneSource source;
    Scene scene;
    OutFile out;
    Error err;
    int rc;

    if (main_load(opts, &scene, &source) != 0)
        return 1;
    if (main_check_target(opts, &scene, &source, opts->save_path, &err) != 0 ||
        main_open_output(&out, opts->save_path, &err) != 0)
        goto fail;
    rc = save_scene(out.fp, &scene, &source, file_display_name(opts->scene_path),
                    opts->save_path, &err);
    if (rc != 0)
        outfile_abort(&out, &err);
    else
        rc = outfile_commit(&out, &err);
    interrupt_watch(NULL);
    if (rc != 0)
        goto fail;
    source_free(&source);
    scene_free(&scene);
    return 0;

fail:
    main_report(&err, "error");
    source_free(&source);
    scene_free(&scene);
    return 1;
}

/* Sets aside from the memory limit what the image and its writing need
 * (and `extra` bytes more), failing when the scene leaves less; builds the
 * mip-maps its texture filters read (scene_filter.h), failing when they
 * would pass the limit; then builds the scene's bounding
 * volume hierarchy (unless opts say not to), failing when it would pass
 * the limit and warning when memory runs out for it, and its light
 * buffers, in *buffers_time seconds. Returns 0, or -1 with *err set. */
static int main_prepare(const Options *opts, const WriterOptions *wopts, size_t extra,
                        Scene *scene, double *buffers_time, Error *err)
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
    rc = scene_prepare_filters(scene);
    if (rc != 0) {
        if (rc == SCENE_OVER_LIMIT)
            error_set(err, opts->scene_path,
                      "the mip-maps of the scene's textures need %s, more than the %s the memory "
                      "limit leaves (--memory-limit; --texture-filter bilinear reads them "
                      "without)",
                      number_bytes(a, scene_filters_memory(scene)),
                      number_bytes(b, scene_memory_left(scene)));
        else
            error_set(err, opts->scene_path, "out of memory for the textures' mip-maps");
        return -1;
    }
    rc = opts->no_accel ? 0 : scene_build_hierarchy(scene, opts->threads);
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
    *buffers_time = process_seconds();
    if (!opts->no_accel)
        scene_build_buffers(scene, opts->threads);
    *buffers_time = process_seconds() - *buffers_time;
    return 0;
}

/* Allocates *img for rows of scene's camera, keeping its linear colours
 * for PFM, gamma-encoded as its model asks (but for a data pass of
 * ropts); returns 0, or -1 with *err set (and *img empty). */
static int main_image(const Options *opts, const WriterOptions *wopts, const Scene *scene,
                      const RenderOptions *ropts, int rows, Image *img, Error *err)
{
    int w = scene->camera.width, h = rows;
    /* A data pass is not a picture: its bytes take no gamma. */
    double gamma = pass_is_data(ropts->pass) ? 0 : model_of(scene)->gamma;

    if (image_init(img, w, h) == 0 &&
        (wopts->format != FORMAT_PFM || image_keep_linear(img) == 0) &&
        (!(gamma > 0) || image_encode_gamma(img, gamma) == 0))
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
    double start = process_seconds();
    int threads;

    if (file_is_terminal(stderr) && !opts->quiet) {
        ropts->progress = main_progress;
        ropts->progress_ctx = &progress;
    }
    progress.start = progress.last_draw = start;
    threads = render(scene, ropts, img, counts);
    *seconds = process_seconds() - start;
    if (progress.drawn) {
        fputs("\r\033[K", stderr); /* erase the bar */
        interrupt_bar(0);
    }
    ropts->progress = NULL;
    return threads;
}

/* Makes *tile opts' tile of the scene's picture rendered with ropts;
 * returns 0, or -1 with *err when it would hold no row. */
static int main_tile(const Options *opts, const Scene *scene, const RenderOptions *ropts,
                     Tile *tile, Error *err)
{
    if (tile_make(tile, opts->tile_k, opts->tile_n, (TileLayout)opts->tile_layout,
                  scene->camera.width, scene->camera.height, adjust_fingerprint(scene, ropts)) == 0)
        return 0;
    error_set(err, opts->scene_path,
              "--tile %d/%d: the picture has %d rows, so at most %d tiles (each holds whole rows)",
              opts->tile_k, opts->tile_n, scene->camera.height, scene->camera.height);
    return -1;
}

/* Says, in *err, why the map `path` of option `option` may not be
 * written: it is the output itself or a file the scene reads, or cannot
 * be made; returns 0 when it may. */
static int main_map_target(const Options *opts, const Scene *scene, const SceneSource *source,
                           const char *path, const char *option, Error *err)
{
    if (strcmp(path, "-") == 0 || strcmp(path, opts->output_path) == 0 ||
        (strcmp(opts->output_path, "-") != 0 && file_same(opts->output_path, path))) {
        error_set(err, path, "%s must name a file of its own, not the output or standard output",
                  option);
        return -1;
    }
    return main_check_target(opts, scene, source, path, err) != 0 ||
                   outfile_check(path, err) != 0
               ? -1
               : 0;
}

/* Says, in *err, why the maps opts asks for may not be written (the
 * render's choices in ropts); returns 0 when they may. */
static int main_maps_target(const Options *opts, const Scene *scene, const SceneSource *source,
                            const RenderOptions *ropts, Error *err)
{
    if (ropts->noise.level > 0 && opts->spp_map &&
        main_map_target(opts, scene, source, opts->spp_map, "--spp-map", err) != 0)
        return -1;
    if (!ropts->indirect.gi_cache || !opts->gi_cache_map)
        return 0;
    if (opts->tile) {
        error_set(err, opts->gi_cache_map,
                  "--gi-cache-map draws the whole picture: render it without --tile");
        return -1;
    }
    return main_map_target(opts, scene, source, opts->gi_cache_map, "--gi-cache-map", err);
}

/* Places the irradiance cache's records of scene under ropts into *cache
 * and has ropts use them; returns 0, or -1 with *err. */
static int main_gi_cache(const Options *opts, const Scene *scene, RenderOptions *ropts,
                         GiCache *cache, IrradianceStats *stats, RayCounts *counts, Error *err)
{
    int rc = irradiance_build(scene, ropts, cache, counts, stats);

    if (rc == SCENE_OVER_LIMIT) {
        error_set(err, opts->scene_path,
                  "the irradiance cache would pass the memory limit (--memory-limit; a larger "
                  "--gi-cache-error makes fewer records)");
        return -1;
    }
    if (rc != 0) {
        error_set(err, opts->scene_path, "out of memory for the irradiance cache");
        return -1;
    }
    ropts->gicache = cache;
    return 0;
}

/* Says whether a render with ropts records each pixel's samples and
 * error: under --noise, when -v or --spp-map will show them. */
static int main_noise_shown(const Options *opts, const RenderOptions *ropts)
{
    return ropts->noise.level > 0 && (opts->verbose || opts->spp_map);
}

/* Returns the bytes main_noise_record() will take for scene's image. */
static size_t main_noise_memory(const Options *opts, const RenderOptions *ropts,
                                const Scene *scene)
{
    if (!main_noise_shown(opts, ropts))
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

    if (!main_noise_shown(opts, ropts))
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

/* Writes img to path as wopts say, replacing path only once the whole image
 * is written; returns 0, or -1 with *err set (and nothing left of a new
 * file). */
static int main_write(const char *path, const Image *img, const WriterOptions *wopts,
                      Error *err)
{
    OutFile out;

    if (main_open_output(&out, path, err) != 0)
        return -1;
    /* An interrupt from here on still finds the watched file: before the move
     * it removes the unfinished file, after it the removal finds nothing. */
    if (writer_write(out.fp, img, wopts) != 0) {
        error_set(err, path, "cannot write the image: %s", strerror(errno));
        outfile_abort(&out, err);
        interrupt_watch(NULL);
        return -1;
    }
    if (outfile_commit(&out, err) != 0) {
        interrupt_watch(NULL);
        return -1;
    }
    interrupt_watch(NULL);
    return 0;
}

/* Writes opts' --spp-map: a width x height heat map of the samples ropts
 * recorded, in the format its name says; returns 0, or -1 with *err. */
static int main_spp_map(const Options *opts, const RenderOptions *ropts, int width, int height,
                        Error *err)
{
    WriterOptions w = {.format = writer_format_for(opts->spp_map), .png_deflate = DEFLATE_FIXED,
                       .jpeg_quality = 95, .jpeg_444 = 1};
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

/* Writes opts' --gi-cache-map: the picture img darkened, the records the
 * camera's rays reach in red; returns 0, or -1 with *err. */
static int main_gi_cache_map(const Options *opts, const Scene *scene, const GiCache *cache,
                             const IrradianceStats *stats, const Image *img, Error *err)
{
    WriterOptions w = {.format = writer_format_for(opts->gi_cache_map),
                       .png_deflate = DEFLATE_FIXED, .jpeg_quality = 95, .jpeg_444 = 1};
    Image map;
    int rc;

    if (image_init(&map, img->width, img->height) != 0) {
        error_set(err, opts->gi_cache_map, "out of memory for the map of records");
        return -1;
    }
    memcpy(map.rgb, img->rgb, 3 * (size_t)img->width * (size_t)img->height);
    irradiance_map(scene, cache, stats->seen, &map);
    rc = main_write(opts->gi_cache_map, &map, &w, err);
    image_free(&map);
    return rc;
}

/* Renders opts' scene to opts' output; returns the exit status. */
static int main_render(const Options *opts)
{
    WriterOptions wopts = {.format = (ImageFormat)opts->format, .ascii = opts->ascii,
                           .png_deflate = opts->png_stored ? DEFLATE_STORED : DEFLATE_FIXED,
                           .jpeg_quality = opts->jpeg_quality, .jpeg_444 = opts->jpeg_444};
    /* The linear colours of PFM would show what the cut-off leaves out. */
    RenderOptions ropts = {.samples = 1, .cutoff = wopts.format == FORMAT_PFM ? 0 : opts->cutoff,
                           .threads = opts->threads};
    RayCounts counts = {0};
    GiCache cache;
    IrradianceStats gi_stats = {0};
    Tile tile;
    char record[TILE_RECORD_MAX];
    double start = process_seconds(), write_start;
    SummaryTimes times = {0};
    SceneSource source;
    Scene scene;
    Image img;
    Error err;
    int rows, threads, rc;

    gicache_init(&cache, 0, 1, 0);
    if (main_load(opts, &scene, &source) != 0)
        return 1;
    times.read = process_seconds() - start;
    if (opts->verbose)
        summary_read(times.read, &source);
    adjust_render(opts, &scene, &ropts);
    if (strcmp(opts->output_path, "-") == 0 && file_is_terminal(stdout)) {
        error_set(&err, "<stdout>", "refusing to write a binary image to a terminal");
        goto fail_scene;
    }
    /* An output that cannot be made is said before a long render. */
    rc = main_check_target(opts, &scene, &source, opts->output_path, &err) != 0 ||
         outfile_check(opts->output_path, &err) != 0 ||
         main_maps_target(opts, &scene, &source, &ropts, &err) != 0;
    source_free(&source); /* the render needs only the scene */
    if (rc != 0 || main_prepare(opts, &wopts, main_noise_memory(opts, &ropts, &scene), &scene,
                                &times.buffers, &err) != 0)
        goto fail_scene;
    times.accel = process_seconds() - start - times.read - times.buffers;
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
    if (main_image(opts, &wopts, &scene, &ropts, rows, &img, &err) != 0)
        goto fail_scene;
    if (main_noise_record(opts, &img, &ropts) != 0) {
        error_set(&err, opts->scene_path, "out of memory");
        goto fail_image_only;
    }
    /* The render needs no file: the output is created once the picture is
     * done, so that nothing is left of it whatever ends the render. */
    if (ropts.indirect.gi_cache &&
        main_gi_cache(opts, &scene, &ropts, &cache, &gi_stats, &counts, &err) != 0)
        goto fail_image_only;
    threads = main_trace(opts, &ropts, &scene, &img, &counts, &times.render);
    write_start = process_seconds();
    if (main_write(opts->output_path, &img, &wopts, &err) != 0 ||
        (opts->spp_map && ropts.spp && main_spp_map(opts, &ropts, img.width, img.height, &err) != 0) ||
        (opts->gi_cache_map && ropts.gicache &&
         main_gi_cache_map(opts, &scene, &cache, &gi_stats, &img, &err) != 0))
        goto fail_image;
    times.write = process_seconds() - write_start;
    times.cache = ropts.gicache ? gi_stats.seconds : 0;
    if (opts->verbose) {
        summary_verbose(&scene, &img, &ropts, opts->spp_map, &times, threads, &counts);
        if (ropts.gicache)
            summary_gi_cache(&cache, &gi_stats, &counts, opts->gi_cache_map);
    } else if (!opts->quiet && file_is_terminal(stderr)) {
        summary_line(strcmp(opts->output_path, "-") == 0 ? "<stdout>" : opts->output_path,
                     &scene, &img, &ropts, process_seconds() - start, threads);
    }
    main_noise_free(&ropts);
    gicache_free(&cache);
    image_free(&img);
    scene_free(&scene);
    return 0;

fail_image:
    interrupt_watch(NULL);
fail_image_only:
    main_noise_free(&ropts);
    gicache_free(&cache);
    image_free(&img);
fail_scene:
    main_report(&err, "error");
    scene_free(&scene);
    return 1;
}

int main(int argc, char **argv)
{
    Options opts;
    char msg[512];
    OptionsAction action;

    process_init(&argc, &argv);
    /* From its first instruction on, an interrupt ends raytrace (130 or 143)
     * and leaves every file as it was, unless its parent ignores it. */
    interrupt_catch("raytrace: interrupted\n");
    action = options_parse(&opts, argc, argv, threads_processors(), msg,
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
