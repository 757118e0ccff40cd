/* Named types of the Demo protocol with every spec feature protocol: enums, bitfields, structs and unions.
 * Generated from the spec: do not edit. */
#ifndef DEMOC_TYPES_H
#define DEMOC_TYPES_H

#include "democodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t democ_flags_t;
/** bit 0:  */
#define DEMOC_FLAGS_OK_MASK ((democ_flags_t)0x1u)
#define DEMOC_FLAGS_OK_SHIFT 0
/** bits 12-15:  */
#define DEMOC_FLAGS_LEVEL_MASK ((democ_flags_t)0xF000u)
#define DEMOC_FLAGS_LEVEL_SHIFT 12
/** bits 0-15:  */
#define DEMOC_FLAGS_ALL_MASK ((democ_flags_t)0xFFFFu)
#define DEMOC_FLAGS_ALL_SHIFT 0

/** Function.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t democ_function_t;
/**  */
#define DEMOC_FUNCTION_WRITE ((democ_function_t)1u)
/**  */
#define DEMOC_FUNCTION_READ ((democ_function_t)2u)
/**  */
#define DEMOC_FUNCTION_SAVE ((democ_function_t)3u)

/** Mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t democ_mode_t;
/**  */
#define DEMOC_MODE_NONE ((democ_mode_t)0u)
/**  */
#define DEMOC_MODE_GPIO ((democ_mode_t)1u)
/**  */
#define DEMOC_MODE_THRESHOLD ((democ_mode_t)2u)
/**  (devices: dev_a) */
#define DEMOC_MODE_FAST ((democ_mode_t)3u)
/**  (devices: dev_b) */
#define DEMOC_MODE_QUIET ((democ_mode_t)3u)

/** Signed.
 * An integer, so that values the spec does not list are kept. */
typedef int16_t democ_signed_t;
/**  */
#define DEMOC_SIGNED_MINUS_ONE ((democ_signed_t)(-1))
/**  */
#define DEMOC_SIGNED_PLUS_ONE ((democ_signed_t)1)

/** GpioParams.  */
typedef struct {
    uint8_t pin;   /*  */
    bool polarity; /*  */
} democ_gpio_params_t;

/** ThresholdParams.  */
typedef struct {
    double low;    /*  */
    double high;   /*  */
    float axes[3]; /*  */
} democ_threshold_params_t;

/** TriggerParams.
 * The member is chosen by a parameter of type democ_mode_t next to it. */
typedef union {
    democ_gpio_params_t gpio;           /* gpio:  */
    democ_threshold_params_t threshold; /* threshold:  */
    uint8_t none_;                      /* members without data */
} democ_trigger_params_t;

#ifdef __cplusplus
}
#endif

#endif
