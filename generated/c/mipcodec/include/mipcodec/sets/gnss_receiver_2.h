/* GNSS Receiver 2 Data Set (descriptor set 0x92): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_GNSS_RECEIVER_2_H
#define MIPC_SETS_GNSS_RECEIVER_2_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_GNSS_RECEIVER_2_SET 0x92

/* ---- llh_position (data): GNSS LLH position */
#define MIPC_GNSS_RECEIVER_2_LLH_POSITION_DESCRIPTOR 0x03

/** GNSS LLH position. Receiver position in the WGS84 geodetic frame (latitude, longitude, heights) with
 * accuracy estimates. */
typedef struct {
    double latitude;                                  /* Latitude (WGS84). [deg] */
    double longitude;                                 /* Longitude (WGS84). [deg] */
    double ellipsoid_height;                          /* Height above the WGS84 ellipsoid. [m] */
    double msl_height;                                /* Height above mean sea level. [m] */
    float horizontal_accuracy;                        /* Horizontal position accuracy estimate. [m] */
    float vertical_accuracy;                          /* Vertical position accuracy estimate. [m] */
    mipc_gnss_llh_position_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_llh_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_LLH_POSITION_MAX_SIZE 42

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_llh_position_encode(const mipc_gnss_receiver_2_llh_position_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_llh_position_decode(const uint8_t *data, size_t len,
                                                       mipc_gnss_receiver_2_llh_position_t *out,
                                                       mipc_decode_error_t *err);

/* ---- ecef_position (data): GNSS ECEF position */
#define MIPC_GNSS_RECEIVER_2_ECEF_POSITION_DESCRIPTOR 0x04

/** GNSS ECEF position. Receiver position in the Earth-centred, Earth-fixed frame with its accuracy estimate.
 */
typedef struct {
    double position[3];                                /* (x, y, z) ECEF position. [m] */
    float position_accuracy;                           /* Position accuracy estimate. [m] */
    mipc_gnss_ecef_position_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_ecef_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_ECEF_POSITION_MAX_SIZE 30

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_ecef_position_encode(const mipc_gnss_receiver_2_ecef_position_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_ecef_position_decode(const uint8_t *data, size_t len,
                                                        mipc_gnss_receiver_2_ecef_position_t *out,
                                                        mipc_decode_error_t *err);

/* ---- ned_velocity (data): GNSS NED velocity */
#define MIPC_GNSS_RECEIVER_2_NED_VELOCITY_DESCRIPTOR 0x05

/** GNSS NED velocity. Receiver velocity in the north-east-down frame, with 3D and ground speed, heading and
 * accuracy estimates. */
typedef struct {
    float velocity[3];                                /* (north, east, down) velocity. [m/s] */
    float speed;                                      /* 3D speed. [m/s] */
    float ground_speed;                               /* Horizontal (ground) speed. [m/s] */
    float heading;                                    /* Heading (direction of travel). [deg] */
    float speed_accuracy;                             /* Speed accuracy estimate. [m/s] */
    float heading_accuracy;                           /* Heading accuracy estimate. [deg] */
    mipc_gnss_ned_velocity_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_ned_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_NED_VELOCITY_MAX_SIZE 34

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_ned_velocity_encode(const mipc_gnss_receiver_2_ned_velocity_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_ned_velocity_decode(const uint8_t *data, size_t len,
                                                       mipc_gnss_receiver_2_ned_velocity_t *out,
                                                       mipc_decode_error_t *err);

/* ---- ecef_velocity (data): GNSS ECEF velocity */
#define MIPC_GNSS_RECEIVER_2_ECEF_VELOCITY_DESCRIPTOR 0x06

/** GNSS ECEF velocity. Receiver velocity in the Earth-centred, Earth-fixed frame with its accuracy estimate.
 */
typedef struct {
    float velocity[3];                                 /* (x, y, z) ECEF velocity. [m/s] */
    float velocity_accuracy;                           /* Velocity accuracy estimate. [m/s] */
    mipc_gnss_ecef_velocity_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_ecef_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_ECEF_VELOCITY_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_ecef_velocity_encode(const mipc_gnss_receiver_2_ecef_velocity_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                        mipc_gnss_receiver_2_ecef_velocity_t *out,
                                                        mipc_decode_error_t *err);

/* ---- dop (data): GNSS dilution of precision */
#define MIPC_GNSS_RECEIVER_2_DOP_DESCRIPTOR 0x07

/** GNSS dilution of precision. Geometric, position, horizontal, vertical, time, northing and easting DOP of
 * the current solution. */
typedef struct {
    float gdop;                              /* Geometric DOP. */
    float pdop;                              /* Position DOP. */
    float hdop;                              /* Horizontal DOP. */
    float vdop;                              /* Vertical DOP. */
    float tdop;                              /* Time DOP. */
    float ndop;                              /* Northing DOP. */
    float edop;                              /* Easting DOP. */
    mipc_gnss_dop_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_dop_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_DOP_MAX_SIZE 30

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_dop_encode(const mipc_gnss_receiver_2_dop_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_dop_decode(const uint8_t *data, size_t len,
                                              mipc_gnss_receiver_2_dop_t *out, mipc_decode_error_t *err);

/* ---- utc_time (data): GNSS UTC time */
#define MIPC_GNSS_RECEIVER_2_UTC_TIME_DESCRIPTOR 0x08

/** GNSS UTC time. UTC date and time of the GNSS solution, with a flag telling whether the leap seconds are
 * known. */
typedef struct {
    uint16_t year;                                    /* Year. */
    uint8_t month;                                    /* Month (1-12). */
    uint8_t day;                                      /* Day of the month (1-31). */
    uint8_t hour;                                     /* Hour (0-23). */
    uint8_t minute;                                   /* Minute (0-59). */
    uint8_t second;                                   /* Second (0-59). */
    uint32_t millisecond;                             /* Millisecond (0-999). [ms] */
    mipc_gnss_utc_time_valid_flags_cv7_t valid_flags; /* Validity of the date/time and of the leap seconds. */
} mipc_gnss_receiver_2_utc_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_UTC_TIME_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_utc_time_encode(const mipc_gnss_receiver_2_utc_time_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_utc_time_decode(const uint8_t *data, size_t len,
                                                   mipc_gnss_receiver_2_utc_time_t *out,
                                                   mipc_decode_error_t *err);

/* ---- gps_time (data): GNSS GPS time */
#define MIPC_GNSS_RECEIVER_2_GPS_TIME_DESCRIPTOR 0x09

/** GNSS GPS time. GPS time of week and week number of the GNSS solution. */
typedef struct {
    double tow;                                   /* GPS time of week. [s] */
    uint16_t week_number;                         /* GPS week number (since 1980). [weeks] */
    mipc_gnss_gps_time_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_gps_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_GPS_TIME_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_gps_time_encode(const mipc_gnss_receiver_2_gps_time_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_gps_time_decode(const uint8_t *data, size_t len,
                                                   mipc_gnss_receiver_2_gps_time_t *out,
                                                   mipc_decode_error_t *err);

/* ---- fix_info (data): GNSS fix information */
#define MIPC_GNSS_RECEIVER_2_FIX_INFO_DESCRIPTOR 0x0B

/** GNSS fix information. Fix type (including RTK float/fixed and differential), number of satellites used and
 * corrections applied. */
typedef struct {
    mipc_gnss_fix_type_cv7_t fix_type;            /* Type of fix. */
    uint8_t num_sv;                               /* Number of satellites used in the solution. */
    mipc_gnss_fix_flags_t fix_flags;              /* Corrections used. */
    mipc_gnss_fix_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_fix_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_FIX_INFO_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_fix_info_encode(const mipc_gnss_receiver_2_fix_info_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_fix_info_decode(const uint8_t *data, size_t len,
                                                   mipc_gnss_receiver_2_fix_info_t *out,
                                                   mipc_decode_error_t *err);

/* ---- hardware_status (data): GNSS hardware status */
#define MIPC_GNSS_RECEIVER_2_HARDWARE_STATUS_DESCRIPTOR 0x0D

/** GNSS hardware status. Power state of the receiver, state of the antenna connection and whether the antenna
 * is powered. */
typedef struct {
    mipc_gnss_receiver_state_t receiver_state;           /* Receiver power state (GX5-45: sensor state). */
    mipc_gnss_antenna_state_t antenna_state;             /* Antenna connection state. */
    mipc_gnss_antenna_power_t antenna_power;             /* Antenna power state. */
    mipc_gnss_hardware_status_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_hardware_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_HARDWARE_STATUS_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_hardware_status_encode(const mipc_gnss_receiver_2_hardware_status_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_hardware_status_decode(const uint8_t *data, size_t len,
                                                          mipc_gnss_receiver_2_hardware_status_t *out,
                                                          mipc_decode_error_t *err);

/* ---- clock_info_2 (data): GNSS clock information 2 */
#define MIPC_GNSS_RECEIVER_2_CLOCK_INFO_2_DESCRIPTOR 0x10

/** GNSS clock information 2. Receiver clock bias and drift, with an accuracy estimate for each. */
typedef struct {
    double bias;                                     /* Receiver clock bias. [s] */
    double drift;                                    /* Receiver clock drift. [s/s] */
    double bias_accuracy_estimate;                   /* Clock bias accuracy estimate. [s] */
    double drift_accuracy_estimate;                  /* Clock drift accuracy estimate. [s/s] */
    mipc_gnss_clock_info2_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_clock_info_2_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_CLOCK_INFO_2_MAX_SIZE 34

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_clock_info_2_encode(const mipc_gnss_receiver_2_clock_info_2_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_clock_info_2_decode(const uint8_t *data, size_t len,
                                                       mipc_gnss_receiver_2_clock_info_2_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gps_leap_seconds (data): GPS leap seconds */
#define MIPC_GNSS_RECEIVER_2_GPS_LEAP_SECONDS_DESCRIPTOR 0x11

/** GPS leap seconds. Number of leap seconds between GPS time and UTC. */
typedef struct {
    uint8_t leap_seconds;                             /* GPS - UTC leap seconds. [s] */
    mipc_gnss_leap_seconds_valid_flags_t valid_flags; /* Validity of the leap seconds. */
} mipc_gnss_receiver_2_gps_leap_seconds_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_GPS_LEAP_SECONDS_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_receiver_2_gps_leap_seconds_encode(const mipc_gnss_receiver_2_gps_leap_seconds_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_gps_leap_seconds_decode(const uint8_t *data, size_t len,
                                                           mipc_gnss_receiver_2_gps_leap_seconds_t *out,
                                                           mipc_decode_error_t *err);

/* ---- sbas_info (data): SBAS information */
#define MIPC_GNSS_RECEIVER_2_SBAS_INFO_DESCRIPTOR 0x12

/** SBAS information. SBAS system and satellite in use, number of corrections and the service status, with the
 * GPS time. */
typedef struct {
    double tow;                                    /* GPS time of week. [s] */
    uint16_t week_number;                          /* GPS week number (since 1980). [weeks] */
    mipc_gnss_sbas_system_t sbas_system;           /* SBAS system. */
    uint8_t sbas_id;                               /* SBAS satellite id. */
    uint8_t count;                                 /* Number of SBAS corrections. */
    mipc_gnss_sbas_status_t sbas_status;           /* Status of the SBAS service. */
    mipc_gnss_sbas_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_receiver_2_sbas_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_SBAS_INFO_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_sbas_info_encode(const mipc_gnss_receiver_2_sbas_info_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_sbas_info_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_receiver_2_sbas_info_t *out,
                                                    mipc_decode_error_t *err);

/* ---- satellite_status (data): Satellite status */
#define MIPC_GNSS_RECEIVER_2_SATELLITE_STATUS_DESCRIPTOR 0x20

/** Satellite status. Sky position and health of one satellite; one field per satellite in view. */
typedef struct {
    uint8_t index;        /* Index of this field among the satellite status fields of this epoch. */
    uint8_t count;        /* Number of satellite status fields in this epoch. */
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number since 1980. [weeks] */
    mipc_gnss_constellation_id_t gnss_id; /* Constellation of the satellite. */
    uint8_t satellite_id;                 /* Satellite number within its constellation. */
    float elevation;                      /* Elevation of the satellite seen from the receiver. [deg] */
    float azimuth;                        /* Azimuth of the satellite seen from the receiver. [deg] */
    bool health;                          /* True if the satellite is healthy. */
    mipc_gnss_satellite_status_valid_flags_t valid_flags; /* Which parameters are valid. */
} mipc_gnss_receiver_2_satellite_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_SATELLITE_STATUS_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_receiver_2_satellite_status_encode(const mipc_gnss_receiver_2_satellite_status_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_satellite_status_decode(const uint8_t *data, size_t len,
                                                           mipc_gnss_receiver_2_satellite_status_t *out,
                                                           mipc_decode_error_t *err);

/* ---- raw (data): Raw observation */
#define MIPC_GNSS_RECEIVER_2_RAW_DESCRIPTOR 0x22

/** Raw observation. Raw pseudorange, carrier phase and Doppler of one signal; one field per tracked signal.
 */
typedef struct {
    uint8_t index;            /* Index of this field among the raw observation fields of this epoch. */
    uint8_t count;            /* Number of raw observation fields in this epoch. */
    double tow;               /* GPS time of week. [s] */
    uint16_t week_number;     /* GPS week number since 1980. [weeks] */
    uint16_t receiver_id;     /* Receiver number (1, 2, ...), or the reference station id when the measurement
                                 comes from RTCM. */
    uint8_t tracking_channel; /* Receiver channel tracking this satellite. */
    mipc_gnss_constellation_id_t gnss_id; /* Constellation of the satellite. */
    uint8_t satellite_id;                 /* Satellite number within its constellation. */
    mipc_gnss_signal_id_t signal_id;      /* Signal the observation is made on. */
    float signal_strength;                /* Carrier-to-noise density ratio. [dB-Hz] */
    mipc_gnss_signal_quality_t quality;   /* Tracking state of the signal. */
    double pseudorange;                   /* Pseudorange. [m] */
    double carrier_phase;                 /* Carrier phase, in carrier periods. [cycles] */
    float doppler;                        /* Doppler shift. [Hz] */
    float range_uncert;                   /* Uncertainty of the pseudorange. [m] */
    float phase_uncert;                   /* Uncertainty of the carrier phase, in carrier periods. [cycles] */
    float doppler_uncert;                 /* Uncertainty of the Doppler shift. [Hz] */
    float lock_time; /* Minimum time the carrier phase has been continuously locked; the largest value
                        reported depends on the receiver. [s] */
    mipc_gnss_raw_valid_flags_t valid_flags; /* Which parameters are valid. */
} mipc_gnss_receiver_2_raw_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_RAW_MAX_SIZE 61

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_raw_encode(const mipc_gnss_receiver_2_raw_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_raw_decode(const uint8_t *data, size_t len,
                                              mipc_gnss_receiver_2_raw_t *out, mipc_decode_error_t *err);

/* ---- gps_ephemeris (data): GPS ephemeris */
#define MIPC_GNSS_RECEIVER_2_GPS_EPHEMERIS_DESCRIPTOR 0x61

/** GPS ephemeris. Broadcast ephemeris of one GPS satellite; one field per satellite. */
typedef struct {
    uint8_t index;        /* Index of this field among the ephemeris fields of this epoch. */
    uint8_t count;        /* Number of ephemeris fields in this epoch. */
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number since 1980. [weeks] */
    uint8_t satellite_id; /* Satellite number within its constellation. */
    uint8_t health;       /* Satellite and signal health. */
    uint8_t iodc;         /* Issue of data, clock: changes whenever the clock data change; lines up data from
                             different sources. */
    uint8_t iode;         /* Issue of data, ephemeris. */
    double t_oc;          /* Reference time of the clock data. [s] */
    double af0;           /* Clock bias. [s] */
    double af1;           /* Clock drift. [s/s] */
    double af2;           /* Clock drift rate. [s/s^2] */
    double t_gd;          /* Group delay. [s] */
    double isc_l1ca;      /* Inter-signal correction, L1. [s] */
    double isc_l2c;       /* Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). [s] */
    double t_oe;          /* Reference time of the ephemeris. [s] */
    double a;             /* Semi-major axis. [m] */
    double a_dot;         /* Rate of the semi-major axis. [m/s] */
    double mean_anomaly;  /* Mean anomaly at the reference time. [rad] */
    double delta_mean_motion;     /* Mean motion difference from the computed value. [rad/s] */
    double delta_mean_motion_dot; /* Rate of the mean motion difference. [rad/s^2] */
    double eccentricity;          /* Orbit eccentricity (dimensionless). */
    double argument_of_perigee;   /* Argument of perigee. [rad] */
    double omega;                 /* Longitude of the ascending node. [rad] */
    double omega_dot;             /* Rate of right ascension. [rad/s] */
    double inclination;           /* Inclination angle. [rad] */
    double inclination_dot;       /* Rate of the inclination angle. [rad/s] */
    double c_ic;                  /* Harmonic correction term, cosine, to the inclination. [rad] */
    double c_is;                  /* Harmonic correction term, sine, to the inclination. [rad] */
    double c_uc;                  /* Harmonic correction term, cosine, to the argument of latitude. [rad] */
    double c_us;                  /* Harmonic correction term, sine, to the argument of latitude. [rad] */
    double c_rc;                  /* Harmonic correction term, cosine, to the orbit radius. [m] */
    double c_rs;                  /* Harmonic correction term, sine, to the orbit radius. [m] */
    mipc_gnss_ephemeris_valid_flags_t valid_flags; /* Which data are valid, and how isc_l2c is to be read. */
} mipc_gnss_receiver_2_gps_ephemeris_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_GPS_EPHEMERIS_MAX_SIZE 218

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_2_gps_ephemeris_encode(const mipc_gnss_receiver_2_gps_ephemeris_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_gps_ephemeris_decode(const uint8_t *data, size_t len,
                                                        mipc_gnss_receiver_2_gps_ephemeris_t *out,
                                                        mipc_decode_error_t *err);

/* ---- glonass_ephemeris (data): GLONASS ephemeris */
#define MIPC_GNSS_RECEIVER_2_GLONASS_EPHEMERIS_DESCRIPTOR 0x62

/** GLONASS ephemeris. Broadcast ephemeris of one GLONASS satellite; one field per satellite. */
typedef struct {
    uint8_t index;        /* Index of this field among the ephemeris fields of this epoch. */
    uint8_t count;        /* Number of ephemeris fields in this epoch. */
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number since 1980. [weeks] */
    uint8_t satellite_id; /* Satellite number within the constellation. */
    int8_t freq_number;   /* GLONASS frequency channel number (-7 to 24). */
    uint32_t tk;          /* Start time of the frame within the current day. [s] */
    uint32_t tb;          /* Reference time of the ephemeris. [s] */
    mipc_gnss_glonass_satellite_type_t sat_type; /* Satellite type. */
    double gamma;      /* Relative deviation of the carrier frequency from nominal (dimensionless). */
    double tau_n;      /* Satellite time correction relative to GLONASS time. [s] */
    double x[3];       /* Satellite position in the PZ-90 frame. [m] */
    float v[3];        /* Satellite velocity in the PZ-90 frame. [m/s] */
    float a[3];        /* Satellite acceleration due to perturbations, PZ-90 frame. [m/s^2] */
    uint8_t health;    /* Satellite health word Bn; non-zero means a malfunction. */
    uint8_t p;         /* Satellite operation mode (see the GLONASS ICD). */
    uint8_t nt;        /* Day number within the four-year period. [days] */
    float delta_tau_n; /* Time difference between the L2 and L1 transmissions. [s] */
    uint8_t ft;        /* User range accuracy index (see the GLONASS ICD). */
    uint8_t en;        /* Age of the current information. [days] */
    uint8_t p1;        /* Interval between adjacent values of tb. [min] */
    uint8_t p2;        /* 1 if tb is odd, 0 if even. */
    uint8_t p3;        /* Number of satellites in the almanac of this frame. */
    uint8_t p4;        /* Non-zero when ephemeris parameters are present. */
    mipc_gnss_glonass_ephemeris_valid_flags_t valid_flags; /* Which data are valid. */
} mipc_gnss_receiver_2_glonass_ephemeris_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_GLONASS_EPHEMERIS_MAX_SIZE 102

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_receiver_2_glonass_ephemeris_encode(const mipc_gnss_receiver_2_glonass_ephemeris_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_glonass_ephemeris_decode(const uint8_t *data, size_t len,
                                                            mipc_gnss_receiver_2_glonass_ephemeris_t *out,
                                                            mipc_decode_error_t *err);

/* ---- galileo_ephemeris (data): Galileo ephemeris */
#define MIPC_GNSS_RECEIVER_2_GALILEO_EPHEMERIS_DESCRIPTOR 0x63

/** Galileo ephemeris. Broadcast ephemeris of one Galileo satellite; one field per satellite. */
typedef struct {
    uint8_t index;        /* Index of this field among the ephemeris fields of this epoch. */
    uint8_t count;        /* Number of ephemeris fields in this epoch. */
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number since 1980. [weeks] */
    uint8_t satellite_id; /* Satellite number within its constellation. */
    uint8_t health;       /* Satellite and signal health. */
    uint8_t iodc;         /* Issue of data, clock: changes whenever the clock data change; lines up data from
                             different sources. */
    uint8_t iode;         /* Issue of data, ephemeris. */
    double t_oc;          /* Reference time of the clock data. [s] */
    double af0;           /* Clock bias. [s] */
    double af1;           /* Clock drift. [s/s] */
    double af2;           /* Clock drift rate. [s/s^2] */
    double t_gd;          /* Group delay. [s] */
    double isc_l1ca;      /* Inter-signal correction, L1. [s] */
    double isc_l2c;       /* Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). [s] */
    double t_oe;          /* Reference time of the ephemeris. [s] */
    double a;             /* Semi-major axis. [m] */
    double a_dot;         /* Rate of the semi-major axis. [m/s] */
    double mean_anomaly;  /* Mean anomaly at the reference time. [rad] */
    double delta_mean_motion;     /* Mean motion difference from the computed value. [rad/s] */
    double delta_mean_motion_dot; /* Rate of the mean motion difference. [rad/s^2] */
    double eccentricity;          /* Orbit eccentricity (dimensionless). */
    double argument_of_perigee;   /* Argument of perigee. [rad] */
    double omega;                 /* Longitude of the ascending node. [rad] */
    double omega_dot;             /* Rate of right ascension. [rad/s] */
    double inclination;           /* Inclination angle. [rad] */
    double inclination_dot;       /* Rate of the inclination angle. [rad/s] */
    double c_ic;                  /* Harmonic correction term, cosine, to the inclination. [rad] */
    double c_is;                  /* Harmonic correction term, sine, to the inclination. [rad] */
    double c_uc;                  /* Harmonic correction term, cosine, to the argument of latitude. [rad] */
    double c_us;                  /* Harmonic correction term, sine, to the argument of latitude. [rad] */
    double c_rc;                  /* Harmonic correction term, cosine, to the orbit radius. [m] */
    double c_rs;                  /* Harmonic correction term, sine, to the orbit radius. [m] */
    mipc_gnss_ephemeris_valid_flags_t valid_flags; /* Which data are valid, and how isc_l2c is to be read. */
} mipc_gnss_receiver_2_galileo_ephemeris_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_GALILEO_EPHEMERIS_MAX_SIZE 218

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_receiver_2_galileo_ephemeris_encode(const mipc_gnss_receiver_2_galileo_ephemeris_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_galileo_ephemeris_decode(const uint8_t *data, size_t len,
                                                            mipc_gnss_receiver_2_galileo_ephemeris_t *out,
                                                            mipc_decode_error_t *err);

/* ---- beidou_ephemeris (data): BeiDou ephemeris */
#define MIPC_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS_DESCRIPTOR 0x64

/** BeiDou ephemeris. Broadcast ephemeris of one BeiDou satellite; one field per satellite. */
typedef struct {
    uint8_t index;        /* Index of this field among the ephemeris fields of this epoch. */
    uint8_t count;        /* Number of ephemeris fields in this epoch. */
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number since 1980. [weeks] */
    uint8_t satellite_id; /* Satellite number within its constellation. */
    uint8_t health;       /* Satellite and signal health. */
    uint8_t iodc;         /* Issue of data, clock: changes whenever the clock data change; lines up data from
                             different sources. */
    uint8_t iode;         /* Issue of data, ephemeris. */
    double t_oc;          /* Reference time of the clock data. [s] */
    double af0;           /* Clock bias. [s] */
    double af1;           /* Clock drift. [s/s] */
    double af2;           /* Clock drift rate. [s/s^2] */
    double t_gd;          /* Group delay. [s] */
    double isc_l1ca;      /* Inter-signal correction, L1. [s] */
    double isc_l2c;       /* Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). [s] */
    double t_oe;          /* Reference time of the ephemeris. [s] */
    double a;             /* Semi-major axis. [m] */
    double a_dot;         /* Rate of the semi-major axis. [m/s] */
    double mean_anomaly;  /* Mean anomaly at the reference time. [rad] */
    double delta_mean_motion;     /* Mean motion difference from the computed value. [rad/s] */
    double delta_mean_motion_dot; /* Rate of the mean motion difference. [rad/s^2] */
    double eccentricity;          /* Orbit eccentricity (dimensionless). */
    double argument_of_perigee;   /* Argument of perigee. [rad] */
    double omega;                 /* Longitude of the ascending node. [rad] */
    double omega_dot;             /* Rate of right ascension. [rad/s] */
    double inclination;           /* Inclination angle. [rad] */
    double inclination_dot;       /* Rate of the inclination angle. [rad/s] */
    double c_ic;                  /* Harmonic correction term, cosine, to the inclination. [rad] */
    double c_is;                  /* Harmonic correction term, sine, to the inclination. [rad] */
    double c_uc;                  /* Harmonic correction term, cosine, to the argument of latitude. [rad] */
    double c_us;                  /* Harmonic correction term, sine, to the argument of latitude. [rad] */
    double c_rc;                  /* Harmonic correction term, cosine, to the orbit radius. [m] */
    double c_rs;                  /* Harmonic correction term, sine, to the orbit radius. [m] */
    mipc_gnss_ephemeris_valid_flags_t valid_flags; /* Which data are valid, and how isc_l2c is to be read. */
} mipc_gnss_receiver_2_beidou_ephemeris_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS_MAX_SIZE 218

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_receiver_2_beidou_ephemeris_encode(const mipc_gnss_receiver_2_beidou_ephemeris_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_2_beidou_ephemeris_decode(const uint8_t *data, size_t len,
                                                           mipc_gnss_receiver_2_beidou_ephemeris_t *out,
                                                           mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_gnss_receiver_2_decode_packet: one member
 * per field the set defines with a single layout (its own, the reserved fields of its kind and the shared
 * data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_gnss_receiver_2_llh_position_t gnss_receiver_2_llh_position;           /* 0x03 */
    mipc_gnss_receiver_2_ecef_position_t gnss_receiver_2_ecef_position;         /* 0x04 */
    mipc_gnss_receiver_2_ned_velocity_t gnss_receiver_2_ned_velocity;           /* 0x05 */
    mipc_gnss_receiver_2_ecef_velocity_t gnss_receiver_2_ecef_velocity;         /* 0x06 */
    mipc_gnss_receiver_2_dop_t gnss_receiver_2_dop;                             /* 0x07 */
    mipc_gnss_receiver_2_utc_time_t gnss_receiver_2_utc_time;                   /* 0x08 */
    mipc_gnss_receiver_2_gps_time_t gnss_receiver_2_gps_time;                   /* 0x09 */
    mipc_gnss_receiver_2_fix_info_t gnss_receiver_2_fix_info;                   /* 0x0B */
    mipc_gnss_receiver_2_hardware_status_t gnss_receiver_2_hardware_status;     /* 0x0D */
    mipc_gnss_receiver_2_clock_info_2_t gnss_receiver_2_clock_info_2;           /* 0x10 */
    mipc_gnss_receiver_2_gps_leap_seconds_t gnss_receiver_2_gps_leap_seconds;   /* 0x11 */
    mipc_gnss_receiver_2_sbas_info_t gnss_receiver_2_sbas_info;                 /* 0x12 */
    mipc_gnss_receiver_2_satellite_status_t gnss_receiver_2_satellite_status;   /* 0x20 */
    mipc_gnss_receiver_2_raw_t gnss_receiver_2_raw;                             /* 0x22 */
    mipc_gnss_receiver_2_gps_ephemeris_t gnss_receiver_2_gps_ephemeris;         /* 0x61 */
    mipc_gnss_receiver_2_glonass_ephemeris_t gnss_receiver_2_glonass_ephemeris; /* 0x62 */
    mipc_gnss_receiver_2_galileo_ephemeris_t gnss_receiver_2_galileo_ephemeris; /* 0x63 */
    mipc_gnss_receiver_2_beidou_ephemeris_t gnss_receiver_2_beidou_ephemeris;   /* 0x64 */
    mipc_shared_event_source_t shared_event_source;                             /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;                           /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                                 /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;               /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta;             /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;                 /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;               /* 0xD8 (shared) */
} mipc_gnss_receiver_2_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_gnss_receiver_2_decode_packet(const uint8_t *payload, size_t len,
                                          mipc_gnss_receiver_2_packet_t *out, mipc_field_entry_fn other,
                                          void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_gnss_receiver_2_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_gnss_receiver_2_layout_members_[25];

#ifdef __cplusplus
}
#endif

#endif
