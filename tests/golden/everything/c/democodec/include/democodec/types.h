/* Named types of the Demo protocol with every spec feature protocol: enums, bitfields, structs and unions.
 * Generated from the spec: do not edit. */
#ifndef DEMO_TYPES_H
#define DEMO_TYPES_H

#include "democodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t demo_flags_t;
/** bit 0:  */
#define DEMO_FLAGS_OK_MASK ((demo_flags_t)0x1u)
#define DEMO_FLAGS_OK_SHIFT 0
/** bits 12-15:  */
#define DEMO_FLAGS_LEVEL_MASK ((demo_flags_t)0xF000u)
#define DEMO_FLAGS_LEVEL_SHIFT 12
/** bits 0-15:  */
#define DEMO_FLAGS_ALL_MASK ((demo_flags_t)0xFFFFu)
#define DEMO_FLAGS_ALL_SHIFT 0

/** Function.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t demo_function_t;
/**  */
#define DEMO_FUNCTION_WRITE ((demo_function_t)1u)
/**  */
#define DEMO_FUNCTION_READ ((demo_function_t)2u)
/**  */
#define DEMO_FUNCTION_SAVE ((demo_function_t)3u)

/** Mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t demo_mode_t;
/**  */
#define DEMO_MODE_NONE ((demo_mode_t)0u)
/**  */
#define DEMO_MODE_GPIO ((demo_mode_t)1u)
/**  */
#define DEMO_MODE_THRESHOLD ((demo_mode_t)2u)
/**  (devices: dev_a) */
#define DEMO_MODE_FAST ((demo_mode_t)3u)
/**  (devices: dev_b) */
#define DEMO_MODE_QUIET ((demo_mode_t)3u)

/** Signed.
 * An integer, so that values the spec does not list are kept. */
typedef int16_t demo_signed_t;
/**  */
#define DEMO_SIGNED_MINUS_ONE ((demo_signed_t)(-1))
/**  */
#define DEMO_SIGNED_PLUS_ONE ((demo_signed_t)1)

/** GpioParams.  */
typedef struct {
    uint8_t pin;   /*  */
    bool polarity; /*  */
} demo_gpio_params_t;

/** ThresholdParams.  */
typedef struct {
    double low;    /*  */
    double high;   /*  */
    float axes[3]; /*  */
} demo_threshold_params_t;

/** TriggerParams.
 * The member is chosen by a parameter of type demo_mode_t next to it. */
typedef union {
    demo_gpio_params_t gpio;           /* gpio:  */
    demo_threshold_params_t threshold; /* threshold:  */
    uint8_t none_;                     /* members without data */
} demo_trigger_params_t;

#ifdef __cplusplus
}
#endif

#endif
