/* A test double of Ultraleap's LeapC API (Gemini 5.x), written for lmc-workbench from the public
 * API reference (docs.ultraleap.com LeapC guide and struct pages; devices/leapc/README.md). It declares
 * the subset the LeapC backend uses with the SDK's own function, struct, field and enum names
 * and values, so devices/leapc/ compiles unchanged against it and against the real header.
 * The behaviour behind it (fake_leapc.cpp) is scripted by tests through fake_leapc.h.
 * Like the real header it is C, packed, and uses anonymous unions/structs; it is included as a
 * SYSTEM header, as the SDK's imported target is. */
#ifndef LMC_FAKE_LEAP_C_H
#define LMC_FAKE_LEAP_C_H

/* The SDK header is a system header for us (imported target); so is its double, also when a
 * file beside it includes it with quotes. */
#if defined(__GNUC__)
#pragma GCC system_header
#endif

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define LEAP_EXPORT
#define LEAP_CALL

#pragma pack(1)

#ifdef __cplusplus
extern "C" {
#endif

typedef enum _eLeapRS {
  eLeapRS_Success = 0x00000000,
  eLeapRS_UnknownError = 0xE2010000,
  eLeapRS_InvalidArgument = 0xE2010001,
  eLeapRS_InsufficientResources = 0xE2010002,
  eLeapRS_InsufficientBuffer = 0xE2010003,
  eLeapRS_Timeout = 0xE2010004,
  eLeapRS_NotConnected = 0xE2010005,
  eLeapRS_HandshakeIncomplete = 0xE2010006,
  eLeapRS_BufferSizeOverflow = 0xE2010007,
  eLeapRS_ProtocolError = 0xE2010008,
  eLeapRS_InvalidClientID = 0xE2010009,
  eLeapRS_UnexpectedClosed = 0xE201000A,
  eLeapRS_UnknownImageFrameRequest = 0xE201000B,
  eLeapRS_UnknownTrackingFrameID = 0xE201000C,
  eLeapRS_RoutineIsNotSeer = 0xE201000D,
  eLeapRS_TimestampTooEarly = 0xE201000E,
  eLeapRS_ConcurrentPoll = 0xE201000F,
  eLeapRS_NotAvailable = 0xE7010002,
  eLeapRS_NotStreaming = 0xE7010004,
  eLeapRS_CannotOpenDevice = 0xE7010005,
  eLeapRS_Unsupported = 0xE7010006
} eLeapRS;

typedef enum _eLeapTrackingMode {
  eLeapTrackingMode_Desktop = 0,
  eLeapTrackingMode_HMD = 1,
  eLeapTrackingMode_ScreenTop = 2,
  eLeapTrackingMode_Unknown = 3
} eLeapTrackingMode;

#define LEAP_SUCCEEDED(rs) (((uint32_t)(rs)&0x80000000u) == 0)
#define LEAP_FAILED(rs) (((uint32_t)(rs)&0x80000000u) != 0)

typedef struct _LEAP_CONNECTION* LEAP_CONNECTION;
typedef struct _LEAP_DEVICE* LEAP_DEVICE;

typedef enum _eLeapConnectionConfig { eLeapConnectionConfig_MultiDeviceAware = 0x00000001 } eLeapConnectionConfig;

typedef struct _LEAP_CONNECTION_CONFIG {
  uint32_t size;
  uint32_t flags;
  const char* server_namespace;
} LEAP_CONNECTION_CONFIG;

typedef enum _eLeapPolicyFlag {
  eLeapPolicyFlag_BackgroundFrames = 0x00000001,
  eLeapPolicyFlag_Images = 0x00000002,
  eLeapPolicyFlag_OptimizeHMD = 0x00000004,
  eLeapPolicyFlag_AllowPauseResume = 0x00000008,
  eLeapPolicyFlag_MapPoints = 0x00000080
} eLeapPolicyFlag;

typedef enum _eLeapEventType {
  eLeapEventType_None = 0,
  eLeapEventType_Connection = 1,
  eLeapEventType_ConnectionLost = 2,
  eLeapEventType_Device = 3,
  eLeapEventType_DeviceFailure = 4,
  eLeapEventType_Policy = 5,
  eLeapEventType_Tracking = 0x100,
  eLeapEventType_ImageRequestError = 0x101,
  eLeapEventType_ImageComplete = 0x102,
  eLeapEventType_LogEvent = 0x103,
  eLeapEventType_DeviceLost = 0x104,
  eLeapEventType_ConfigResponse = 0x105,
  eLeapEventType_ConfigChange = 0x106,
  eLeapEventType_DeviceStatusChange = 0x107,
  eLeapEventType_DroppedFrame = 0x108,
  eLeapEventType_Image = 0x109,
  eLeapEventType_PointMappingChange = 0x10A,
  eLeapEventType_TrackingMode = 0x10B,
  eLeapEventType_LogEvents = 0x10C,
  eLeapEventType_HeadPose = 0x10D,
  eLeapEventType_Eyes = 0x10E,
  eLeapEventType_IMU = 0x10F
} eLeapEventType;

typedef enum _eLeapDeviceStatus {
  eLeapDeviceStatus_Streaming = 0x00000001,
  eLeapDeviceStatus_Paused = 0x00000002,
  eLeapDeviceStatus_Robust = 0x00000004,
  eLeapDeviceStatus_Smudged = 0x00000008,
  eLeapDeviceStatus_LowResource = 0x00000010,
  eLeapDeviceStatus_UnknownFailure = 0xE8010000,
  eLeapDeviceStatus_BadCalibration = 0xE8010001,
  eLeapDeviceStatus_BadFirmware = 0xE8010002,
  eLeapDeviceStatus_BadTransport = 0xE8010003,
  eLeapDeviceStatus_BadControl = 0xE8010004
} eLeapDeviceStatus;

typedef enum _eLeapDevicePID {
  eLeapDevicePID_Unknown = 0x0000,
  eLeapDevicePID_Peripheral = 0x0003,
  eLeapDevicePID_Rigel = 0x1202,
  eLeapDevicePID_SIR170 = 0x1203,
  eLeapDevicePID_3Di = 0x1204,
  eLeapDevicePID_LMC2 = 0x1206
} eLeapDevicePID;

typedef enum _eLeapServiceDisposition {
  eLeapServiceState_LowFpsDetected = 0x00000001,
  eLeapServiceState_PoorPerformancePause = 0x00000002,
  eLeapServiceState_TrackingErrorUnknown = 0x00000004
} eLeapServiceDisposition;

typedef enum _eLeapHandType { eLeapHandType_Left = 0, eLeapHandType_Right = 1 } eLeapHandType;

typedef enum _eLeapDroppedFrameType {
  eLeapDroppedFrameType_PreprocessingQueue = 0,
  eLeapDroppedFrameType_TrackingQueue = 1,
  eLeapDroppedFrameType_Other = 2
} eLeapDroppedFrameType;

typedef struct _LEAP_DEVICE_REF {
  void* handle;
  uint32_t id;
} LEAP_DEVICE_REF;

typedef struct _LEAP_CONNECTION_EVENT {
  uint32_t flags;
} LEAP_CONNECTION_EVENT;

typedef struct _LEAP_CONNECTION_LOST_EVENT {
  uint32_t flags;
} LEAP_CONNECTION_LOST_EVENT;

typedef struct _LEAP_DEVICE_EVENT {
  uint32_t flags;
  LEAP_DEVICE_REF device;
  uint32_t status;
} LEAP_DEVICE_EVENT;

typedef struct _LEAP_DEVICE_FAILURE_EVENT {
  eLeapDeviceStatus status;
  LEAP_DEVICE hDevice;
} LEAP_DEVICE_FAILURE_EVENT;

typedef struct _LEAP_DEVICE_STATUS_CHANGE_EVENT {
  LEAP_DEVICE_REF device;
  uint32_t last_status;
  uint32_t status;
} LEAP_DEVICE_STATUS_CHANGE_EVENT;

/* The policies in force after a policy request (answered asynchronously, per device on a
 * multi-device-aware connection: the message's device_id names it). */
typedef struct _LEAP_POLICY_EVENT {
  uint32_t reserved;
  uint32_t current_policy;
} LEAP_POLICY_EVENT;

/* The tracking mode in force after a tracking-mode request or a change made elsewhere. */
typedef struct _LEAP_TRACKING_MODE_EVENT {
  uint32_t reserved;
  eLeapTrackingMode current_tracking_mode;
} LEAP_TRACKING_MODE_EVENT;

typedef struct _LEAP_DROPPED_FRAME_EVENT {
  int64_t frame_id;
  eLeapDroppedFrameType type;
} LEAP_DROPPED_FRAME_EVENT;

typedef struct _LEAP_DEVICE_INFO {
  uint32_t size;
  uint32_t status;
  uint32_t caps;
  eLeapDevicePID pid;
  uint32_t baseline;
  uint32_t serial_length;
  char* serial;
  float h_fov;
  float v_fov;
  uint32_t range;
} LEAP_DEVICE_INFO;

typedef struct _LEAP_VECTOR {
  union {
    float v[3];
    struct {
      float x;
      float y;
      float z;
    };
  };
} LEAP_VECTOR;

typedef struct _LEAP_QUATERNION {
  union {
    float v[4];
    struct {
      float x;
      float y;
      float z;
      float w;
    };
  };
} LEAP_QUATERNION;

typedef struct _LEAP_BONE {
  LEAP_VECTOR prev_joint;
  LEAP_VECTOR next_joint;
  float width;
  LEAP_QUATERNION rotation;
} LEAP_BONE;

typedef struct _LEAP_DIGIT {
  int32_t finger_id;
  union {
    LEAP_BONE bones[4];
    struct {
      LEAP_BONE metacarpal;
      LEAP_BONE proximal;
      LEAP_BONE intermediate;
      LEAP_BONE distal;
    };
  };
  uint32_t is_extended;
} LEAP_DIGIT;

typedef struct _LEAP_PALM {
  LEAP_VECTOR position;
  LEAP_VECTOR stabilized_position;
  LEAP_VECTOR velocity;
  LEAP_VECTOR normal;
  float width;
  LEAP_VECTOR direction;
  LEAP_QUATERNION orientation;
} LEAP_PALM;

typedef struct _LEAP_HAND {
  uint32_t id;
  uint32_t flags;
  eLeapHandType type;
  float confidence;
  uint64_t visible_time;
  float pinch_distance;
  float grab_angle;
  float pinch_strength;
  float grab_strength;
  LEAP_PALM palm;
  union {
    struct {
      LEAP_DIGIT thumb;
      LEAP_DIGIT index;
      LEAP_DIGIT middle;
      LEAP_DIGIT ring;
      LEAP_DIGIT pinky;
    };
    LEAP_DIGIT digits[5];
  };
  LEAP_BONE arm;
} LEAP_HAND;

typedef struct _LEAP_FRAME_HEADER {
  void* reserved;
  int64_t frame_id;
  int64_t timestamp;
} LEAP_FRAME_HEADER;

typedef struct _LEAP_TRACKING_EVENT {
  LEAP_FRAME_HEADER info;
  int64_t tracking_frame_id;
  uint32_t nHands;
  LEAP_HAND* pHands;
  float framerate;
} LEAP_TRACKING_EVENT;

typedef struct _LEAP_CONNECTION_MESSAGE {
  uint32_t size;
  eLeapEventType type;
  union {
    const void* pointer;
    const LEAP_CONNECTION_EVENT* connection_event;
    const LEAP_CONNECTION_LOST_EVENT* connection_lost_event;
    const LEAP_DEVICE_EVENT* device_event;
    const LEAP_DEVICE_FAILURE_EVENT* device_failure_event;
    const LEAP_TRACKING_EVENT* tracking_event;
    const LEAP_DEVICE_STATUS_CHANGE_EVENT* device_status_change_event;
    const LEAP_POLICY_EVENT* policy_event;
    const LEAP_TRACKING_MODE_EVENT* tracking_mode_event;
    const LEAP_DROPPED_FRAME_EVENT* dropped_frame_event;
  };
  uint32_t device_id;
} LEAP_CONNECTION_MESSAGE;

LEAP_EXPORT eLeapRS LEAP_CALL LeapCreateConnection(const LEAP_CONNECTION_CONFIG* pConfig,
                                                   LEAP_CONNECTION* phConnection);
LEAP_EXPORT eLeapRS LEAP_CALL LeapOpenConnection(LEAP_CONNECTION hConnection);
LEAP_EXPORT eLeapRS LEAP_CALL LeapPollConnection(LEAP_CONNECTION hConnection, uint32_t timeout,
                                                 LEAP_CONNECTION_MESSAGE* evt);
LEAP_EXPORT void LEAP_CALL LeapCloseConnection(LEAP_CONNECTION hConnection);
LEAP_EXPORT void LEAP_CALL LeapDestroyConnection(LEAP_CONNECTION hConnection);
LEAP_EXPORT eLeapRS LEAP_CALL LeapSetPolicyFlags(LEAP_CONNECTION hConnection, uint64_t set, uint64_t clear);
/* Per device (multi-device-aware connections; LeapSetPolicyFlags reaches only the primary device). @since 5.4.0 */
LEAP_EXPORT eLeapRS LEAP_CALL LeapSetPolicyFlagsEx(LEAP_CONNECTION hConnection, LEAP_DEVICE hDevice, uint64_t set,
                                                   uint64_t clear);
/* Per device; asynchronous: the answer is a TrackingMode event for the device. @since 5.4.0 */
LEAP_EXPORT eLeapRS LEAP_CALL LeapSetTrackingModeEx(LEAP_CONNECTION hConnection, LEAP_DEVICE hDevice,
                                                    eLeapTrackingMode mode);
/* Per device; asynchronous: answered by a TrackingMode event with the mode in force. @since 5.4.0 */
LEAP_EXPORT eLeapRS LEAP_CALL LeapGetTrackingModeEx(LEAP_CONNECTION hConnection, LEAP_DEVICE hDevice);
LEAP_EXPORT eLeapRS LEAP_CALL LeapOpenDevice(LEAP_DEVICE_REF rDevice, LEAP_DEVICE* phDevice);
LEAP_EXPORT void LEAP_CALL LeapCloseDevice(LEAP_DEVICE hDevice);
LEAP_EXPORT eLeapRS LEAP_CALL LeapGetDeviceInfo(LEAP_DEVICE hDevice, LEAP_DEVICE_INFO* info);
LEAP_EXPORT eLeapRS LEAP_CALL LeapSubscribeEvents(LEAP_CONNECTION hConnection, LEAP_DEVICE hDevice);
LEAP_EXPORT eLeapRS LEAP_CALL LeapUnsubscribeEvents(LEAP_CONNECTION hConnection, LEAP_DEVICE hDevice);
LEAP_EXPORT int64_t LEAP_CALL LeapGetNow(void);

#ifdef __cplusplus
}
#endif

#pragma pack()

#endif /* LMC_FAKE_LEAP_C_H */
