/* Replays saved inputs through a fuzz harness without libFuzzer (built with gcc/g++ and
 * -fsanitize=address,undefined by `make test-fuzz-regressions`): every FILE argument, and every
 * regular file in a DIRECTORY argument, is passed to LLVMFuzzerTestOneInput once. A failed check
 * or a sanitizer report aborts with a non-zero status; otherwise it prints how many ran. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#ifdef __cplusplus
extern "C"
#endif
    int
    LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path) {
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t len = 0;
    size_t cap = 0;
    size_t n;
    uint8_t chunk[4096];
    if (!f) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return -1;
    }
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) {
        if (len + n > cap) {
            uint8_t *bigger;
            cap = (len + n) * 2;
            bigger = (uint8_t *)realloc(buf, cap);
            if (!bigger) {
                free(buf);
                fclose(f);
                return -1;
            }
            buf = bigger;
        }
        memcpy(buf + len, chunk, n);
        len += n;
    }
    fclose(f);
    {
        /* an exact-size copy, so that reading past the input is a sanitizer report */
        uint8_t *exact = (uint8_t *)malloc(len ? len : 1);
        if (!exact) {
            free(buf);
            return -1;
        }
        if (len) {
            memcpy(exact, buf, len);
        }
        free(buf);
        fprintf(stderr, "replay: %s\n", path);
        LLVMFuzzerTestOneInput(exact, len);
        free(exact);
    }
    return 1;
}

static int cmp_names(const void *a, const void *b) {
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int main(int argc, char **argv) {
    int i;
    long count = 0;
    for (i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "replay: no such file or directory: %s\n", argv[i]);
            return 2;
        }
        if (S_ISDIR(st.st_mode)) {
            DIR *dir = opendir(argv[i]);
            struct dirent *de;
            char **names = NULL;
            size_t n = 0;
            size_t k;
            if (!dir) {
                return 2;
            }
            while ((de = readdir(dir)) != NULL) {
                char *path;
                struct stat fst;
                char **bigger;
                if (de->d_name[0] == '.') {
                    continue;
                }
                path = (char *)malloc(strlen(argv[i]) + strlen(de->d_name) + 2);
                if (!path) {
                    return 2;
                }
                sprintf(path, "%s/%s", argv[i], de->d_name);
                if (stat(path, &fst) != 0 || !S_ISREG(fst.st_mode)) {
                    free(path);
                    continue;
                }
                bigger = (char **)realloc(names, (n + 1) * sizeof *names);
                if (!bigger) {
                    return 2;
                }
                names = bigger;
                names[n++] = path;
            }
            closedir(dir);
            qsort(names, n, sizeof *names, cmp_names);
            for (k = 0; k < n; k++) {
                if (run_file(names[k]) < 0) {
                    return 2;
                }
                count++;
                free(names[k]);
            }
            free(names);
        } else {
            if (run_file(argv[i]) < 0) {
                return 2;
            }
            count++;
        }
    }
    printf("replay: %ld inputs passed\n", count);
    return 0;
}
