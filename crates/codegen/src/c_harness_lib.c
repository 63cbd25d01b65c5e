/* ---- scenario replay (the format of `statecheck sim --scenario`) ---- */

static state_t S;
static inputs_t I;
static outputs_t O;
static int64_t V[N_SLOTS + 1];
static uint64_t TICK;
static int STOPPED; /* 0 running, 1 violated, 2 run-time error, 3 assume violated */
static const char *STOP_PROPERTY;
static int STEP_STATUS;
static unsigned STOP_ASSUME;
static int PRINT = 1;

static char *trim(char *s) {
    char *e;
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
    e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n')) *--e = 0;
    return s;
}

static int parse_int(const char *t, int64_t *out) {
    int neg = 0, base = 10, any = 0;
    uint64_t v = 0;
    if (*t == '-') { neg = 1; t++; }
    if (t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) { base = 16; t += 2; }
    else if (t[0] == '0' && t[1] == 'b') { base = 2; t += 2; }
    for (; *t; t++) {
        int d;
        if (*t == '_') continue;
        if (*t >= '0' && *t <= '9') d = *t - '0';
        else if (*t >= 'a' && *t <= 'f') d = *t - 'a' + 10;
        else if (*t >= 'A' && *t <= 'F') d = *t - 'A' + 10;
        else return 0;
        if (d >= base) return 0;
        if (v > (UINT64_MAX - (uint64_t)d) / (uint64_t)base) return 0;
        v = v * (uint64_t)base + (uint64_t)d;
        any = 1;
    }
    /* the magnitude of INT64_MIN is INT64_MAX + 1: every int64 value reads back */
    if (!any || v > (uint64_t)INT64_MAX + (uint64_t)neg) return 0;
    if (neg) *out = v > (uint64_t)INT64_MAX ? INT64_MIN : -(int64_t)v;
    else *out = (int64_t)v;
    return 1;
}

static int parse_value(const in_desc *d, const char *t, int64_t *out) {
    int k;
    const char *dot;
    if (d->kind == 0 || d->is_event) {
        if (!strcmp(t, "true") || !strcmp(t, "1")) { *out = 1; return 1; }
        if (!strcmp(t, "false") || !strcmp(t, "0")) { *out = 0; return 1; }
        return 0;
    }
    if (d->kind == 1) return parse_int(t, out);
    dot = strrchr(t, '.');
    if (dot) t = dot + 1;
    for (k = 0; k < d->n_lits; k++) {
        if (!strcmp(d->lits[k], t)) { *out = k; return 1; }
    }
    return 0;
}

static int resolve(const char *name) {
    unsigned k;
    int found = -1, count = 0;
    for (k = 0; INPUTS[k].name; k++) {
        if (!strcmp(INPUTS[k].name, name)) return (int)k;
    }
    for (k = 0; INPUTS[k].name; k++) {
        const char *dot = strrchr(INPUTS[k].name, '.');
        const char *bare = dot ? dot + 1 : INPUTS[k].name;
        if (!strcmp(bare, name)) { found = (int)k; count++; }
    }
    return count == 1 ? found : -1;
}

/* One tick with the inputs in I: assumes, step, trace, properties (as `statecheck sim`). */
static void run_tick(void) {
    const char *viol;
    SLOTS(&S, &I, &O, V);
    if (!assumes_hold(V, &STOP_ASSUME)) { STOPPED = 3; return; }
    STEP_STATUS = STEP(&S, &I, &O);
    if (STEP_STATUS != SC_OK) { STOPPED = 2; return; }
    SLOTS(&S, &I, &O, V);
    if (PRINT) {
        if (TICK > 0) putchar(',');
        print_tick(TICK, V);
    }
    viol = first_violation(TICK, V);
    if (viol) { STOPPED = 1; STOP_PROPERTY = viol; return; }
    TICK++;
}

static void die(int line, const char *msg, const char *what) {
    fprintf(stderr, "error: scenario line %d: %s `%s`\n", line, msg, what);
    exit(2);
}

static void replay(FILE *f) {
    static char buf[1 << 16];
    int line_no = 0;
    int64_t idx[256], val[256];
    while (!STOPPED && fgets(buf, sizeof buf, f)) {
        char *content, *star, *body, *item;
        long repeat = 1, r;
        unsigned n = 0, k;
        line_no++;
        content = buf;
        if (strchr(content, '#')) *strchr(content, '#') = 0;
        content = trim(content);
        if (!*content) continue;
        star = strrchr(content, '*');
        if (star) {
            char *end;
            *star = 0;
            repeat = strtol(trim(star + 1), &end, 10);
            if (repeat < 1 || *end) die(line_no, "bad repeat count", star + 1);
        }
        body = trim(content);
        if (strcmp(body, "-") != 0) {
            for (item = strtok(body, ","); item; item = strtok(0, ",")) {
                char *eq = strchr(item, '='), *name;
                int64_t v = 1;
                int in;
                if (eq) *eq = 0;
                name = trim(item);
                in = resolve(name);
                if (in < 0) die(line_no, "unknown or ambiguous input", name);
                if (eq) {
                    if (!parse_value(&INPUTS[in], trim(eq + 1), &v)) die(line_no, "bad value for", name);
                    if (v < INPUTS[in].lo || v > INPUTS[in].hi) die(line_no, "value out of range for", name);
                } else if (!INPUTS[in].is_event) {
                    die(line_no, "not an event; give it a value:", name);
                }
                if (n == 256) die(line_no, "too many items", name);
                idx[n] = in;
                val[n] = v;
                n++;
            }
        }
        for (r = 0; r < repeat && !STOPPED; r++) {
            for (k = 0; INPUTS[k].name; k++) {
                if (INPUTS[k].is_event) set_input(&I, k, 0);
            }
            for (k = 0; k < n; k++) set_input(&I, (unsigned)idx[k], val[k]);
            run_tick();
        }
    }
}

static uint64_t RNG = 0x9E3779B97F4A7C15ull;
static uint64_t rnd(void) {
    RNG ^= RNG << 13;
    RNG ^= RNG >> 7;
    RNG ^= RNG << 17;
    return RNG;
}

/* N ticks of uniformly random inputs within their types and the assumes (benchmarks). */
static void random_run(uint64_t n) {
    unsigned k;
    int tries;
    while (!STOPPED && TICK < n) {
        for (tries = 0; tries < 10000; tries++) {
            unsigned which;
            for (k = 0; INPUTS[k].name; k++) {
                uint64_t span = (uint64_t)INPUTS[k].hi - (uint64_t)INPUTS[k].lo + 1u;
                uint64_t x = span == 0 ? rnd() : rnd() % span;
                set_input(&I, k, (int64_t)((uint64_t)INPUTS[k].lo + x));
            }
            SLOTS(&S, &I, &O, V);
            if (assumes_hold(V, &which)) break;
        }
        run_tick();
    }
}

static const char *status_property(int st) {
    switch (st) {
    case SC_ERR_DIVISION_BY_ZERO: return "no_division_by_zero";
    case SC_ERR_BAD_SHIFT: return "no_bad_shift";
    default: return "no_range_overflow";
    }
}

static const char *status_text(int st) {
    switch (st) {
    case SC_ERR_RANGE: return "value out of range";
    case SC_ERR_DIVISION_BY_ZERO: return "division by zero";
    case SC_ERR_BAD_SHIFT: return "shift amount outside 0..62";
    default: return "arithmetic overflow";
    }
}

int main(int argc, char **argv) {
    int k;
    for (k = 0; k <= N_REACH; k++) reached[k] = -1;
    INIT(&S, &I, &O);
    if (argc == 4 && !strcmp(argv[1], "--random")) {
        uint64_t n = strtoull(argv[2], 0, 10);
        RNG ^= strtoull(argv[3], 0, 10) * 0x2545F4914F6CDD1Dull;
        if (RNG == 0) RNG = 1;
        PRINT = 0;
        random_run(n);
        printf("{\"ticks_run\":%llu,\"stopped\":%d}\n", (unsigned long long)TICK, STOPPED);
        return STOPPED == 0 ? 0 : STOPPED == 1 ? 4 : 1;
    }
    if (argc != 2) {
        fprintf(stderr, "usage: %s SCENARIO_FILE | --random N SEED\n", argv[0]);
        return 2;
    } else {
        FILE *f = strcmp(argv[1], "-") ? fopen(argv[1], "r") : stdin;
        if (!f) { fprintf(stderr, "error: cannot read `%s`\n", argv[1]); return 2; }
        printf("{\"ticks\":[");
        replay(f);
        if (f != stdin) fclose(f);
    }
    printf("],\"result\":{");
    switch (STOPPED) {
    case 0: printf("\"status\":\"completed\",\"message\":\"run completed\""); break;
    case 1:
        printf("\"status\":\"violated\",\"message\":\"property `%s` violated at tick %llu\",\"tick\":%llu,\"property\":\"%s\"",
               STOP_PROPERTY, (unsigned long long)TICK, (unsigned long long)TICK, STOP_PROPERTY);
        break;
    case 2:
        printf("\"status\":\"runtime_error\",\"message\":\"run-time error at tick %llu: %s at site %lu\",\"tick\":%llu,\"property\":\"%s\"",
               (unsigned long long)TICK, status_text(STEP_STATUS), (unsigned long)O.error_site,
               (unsigned long long)TICK, status_property(STEP_STATUS));
        break;
    default:
        printf("\"status\":\"assume_violated\",\"message\":\"the inputs of tick %llu violate `assume` #%u of the system\"",
               (unsigned long long)TICK, STOP_ASSUME + 1);
        break;
    }
    printf("},\"reached\":{");
    for (k = 0; k < N_REACH; k++) {
        if (k) putchar(',');
        if (reached[k] < 0) printf("\"%s\":null", REACH_NAMES[k]);
        else printf("\"%s\":%lld", REACH_NAMES[k], (long long)reached[k]);
    }
    printf("}}\n");
    return STOPPED == 0 ? 0 : STOPPED == 1 ? 4 : 1;
}
