"""Golden vectors and stream corpus of mscipcodec (generated from tests/vectors/mscip/ and
tests/streams/mscip/), checked by tests/test_vectors.py."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import mscipcodec as package

__all__ = ["CASES", "package"]

CASES = [
    {
        "name": "mscip_ping_command",
        "hex": "a5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:10",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}'],
    },
    {
        "name": "mscip_ping_reply",
        "hex": "a5a5010480020200d3cf",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:26",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":2,"error_code":0}}]}'
        ],
    },
    {
        "name": "get_device_messages_command",
        "hex": "a5a5010203005027",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:36",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"get_device_messages","values":{}}]}'],
    },
    {
        "name": "get_device_messages_reply",
        "hex": "a5a5010e80020300830801020103010401057b57",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:46",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":3,"error_code":0}},{"descriptor":131,"name":"device_messages","values":{"messages":[{"message_type":1,"message_code":2},{"message_type":1,"message_code":3},{"message_type":1,"message_code":4},{"message_type":1,"message_code":5}]}}]}'
        ],
    },
    {
        "name": "get_device_messages_reply_published",
        "hex": "a5a5010f80030300830801020103010401057d73",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mscip/base.yaml:62",
        "expect": ['{"offset":0,"skipped":"a5a5010f80030300830801020103010401057d73"}'],
    },
    {
        "name": "get_device_messages_reply_table",
        "hex": "a5a5010f80020300830801020103010401057d73",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mscip/base.yaml:78",
        "expect": ['{"offset":0,"skipped":"a5a5010f80020300830801020103010401057d73"}'],
    },
    {
        "name": "get_device_messages_reply_full",
        "hex": "a5a5014080020300833a0102010301040105010601070108010902010203020402050206020702080209020a020b020c020da281a282a283a284a285a286a287a288a289d169",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:93",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":3,"error_code":0}},{"descriptor":131,"name":"device_messages","values":{"messages":[{"message_type":1,"message_code":2},{"message_type":1,"message_code":3},{"message_type":1,"message_code":4},{"message_type":1,"message_code":5},{"message_type":1,"message_code":6},{"message_type":1,"message_code":7},{"message_type":1,"message_code":8},{"message_type":1,"message_code":9},{"message_type":2,"message_code":1},{"message_type":2,"message_code":3},{"message_type":2,"message_code":4},{"message_type":2,"message_code":5},{"message_type":2,"message_code":6},{"message_type":2,"message_code":7},{"message_type":2,"message_code":8},{"message_type":2,"message_code":9},{"message_type":2,"message_code":10},{"message_type":2,"message_code":11},{"message_type":2,"message_code":12},{"message_type":2,"message_code":13},{"message_type":162,"message_code":129},{"message_type":162,"message_code":130},{"message_type":162,"message_code":131},{"message_type":162,"message_code":132},{"message_type":162,"message_code":133},{"message_type":162,"message_code":134},{"message_type":162,"message_code":135},{"message_type":162,"message_code":136},{"message_type":162,"message_code":137}]}}]}'
        ],
    },
    {
        "name": "get_device_messages_reply_empty",
        "hex": "a5a50106800203008300598d",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:109",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":3,"error_code":0}},{"descriptor":131,"name":"device_messages","values":{"messages":[]}}]}'
        ],
    },
    {
        "name": "mscip_device_reset_command",
        "hex": "a5a5010204005129",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:123",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":4,"name":"device_reset","values":{}}]}'],
    },
    {
        "name": "mscip_device_reset_reply",
        "hex": "a5a5010480020400d5d3",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:133",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":4,"error_code":0}}]}'
        ],
    },
    {
        "name": "get_device_model_command",
        "hex": "a5a501020500522b",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:143",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":5,"name":"get_device_model","values":{}}]}'],
    },
    {
        "name": "get_device_model_reply",
        "hex": "a5a501168002050085102020202020204d535f494d5533303230ec54",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:153",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":5,"error_code":0}},{"descriptor":133,"name":"device_model","values":{"model":"      MS_IMU3020"}}]}'
        ],
    },
    {
        "name": "get_device_sn_command",
        "hex": "a5a501020600532d",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:166",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":6,"name":"get_device_sn","values":{}}]}'],
    },
    {
        "name": "get_device_sn_reply",
        "hex": "a5a5011680020600861020202020202020202020203230323638e123",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:176",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":6,"error_code":0}},{"descriptor":134,"name":"device_sn","values":{"serial_number":"           20268"}}]}'
        ],
    },
    {
        "name": "get_device_sn_reply_published",
        "hex": "a5a501168002060086102020202020202020202020203230323638e123",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mscip/base.yaml:192",
        "expect": ['{"offset":0,"skipped":"a5a501168002060086102020202020202020202020203230323638e123"}'],
    },
    {
        "name": "get_device_fw_command",
        "hex": "a5a501020700542f",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:209",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":7,"name":"get_device_fw","values":{}}]}'],
    },
    {
        "name": "get_device_fw_reply",
        "hex": "a5a50116800207008710202020202020202020525f315f325f33a625",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:219",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":7,"error_code":0}},{"descriptor":135,"name":"device_fw","values":{"firmware":"         R_1_2_3"}}]}'
        ],
    },
    {
        "name": "get_device_fw_reply_published",
        "hex": "a5a501168002070087102020202020202020202020525f315f325f33a625",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mscip/base.yaml:235",
        "expect": ['{"offset":0,"skipped":"a5a501168002070087102020202020202020202020525f315f325f33a625"}'],
    },
    {
        "name": "get_device_cal_command",
        "hex": "a5a5010208005531",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:250",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":8,"name":"get_device_cal","values":{}}]}'],
    },
    {
        "name": "get_device_cal_reply",
        "hex": "a5a5011680020800881020202020202030352d30382d323031353210",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:260",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":8,"error_code":0}},{"descriptor":136,"name":"device_cal","values":{"date":"      05-08-2015"}}]}'
        ],
    },
    {
        "name": "get_device_cal_reply_published",
        "hex": "a5a50116800208008810202020202030352d30382d323031353210",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mscip/base.yaml:276",
        "expect": ['{"offset":0,"skipped":"a5a50116800208008810202020202030352d30382d323031353210"}'],
    },
    {
        "name": "correlate_gps_time_command",
        "hex": "a5a501080906072f000002ff99af",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:291",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":9,"name":"correlate_gps_time","values":{"week":1839,"seconds":767}}]}'
        ],
    },
    {
        "name": "correlate_gps_time_reply",
        "hex": "a5a5010480020900dadd",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:304",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":9,"error_code":0}}]}'
        ],
    },
    {
        "name": "mscip_nack_checksum_error",
        "hex": "a5a5010480020201d4d0",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:314",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":2,"error_code":1}}]}'
        ],
    },
    {
        "name": "mscip_nack_invalid_message_type",
        "hex": "a5a5030480020102d6db",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:328",
        "expect": [
            '{"offset":0,"set":3,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":1,"error_code":2}}]}'
        ],
    },
    {
        "name": "mscip_nack_invalid_message_code",
        "hex": "a5a5010480020a03dee2",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:344",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":10,"error_code":3}}]}'
        ],
    },
    {
        "name": "mscip_nack_invalid_parameter",
        "hex": "a5a5020480020104d7d7",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:358",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":1,"error_code":4}}]}'
        ],
    },
    {
        "name": "get_device_model_nack",
        "hex": "a5a5010480020501d7d6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:372",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":5,"error_code":1}}]}'
        ],
    },
    {
        "name": "correlate_gps_time_command_end_of_week",
        "hex": "a5a501080906096000093a7f8dbb",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/base.yaml:386",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":9,"name":"correlate_gps_time","values":{"week":2400,"seconds":604799}}]}'
        ],
    },
    {
        "name": "encode_input_irregular_size_byte",
        "hex": "a5a502030500025688",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/encode_input.yaml:5",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":2}}]}'],
    },
    {
        "name": "uart_baud_rate_write",
        "hex": "a5a502070105010001c2001d84",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:12",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":1,"name":"uart_baud_rate","values":{"function":1,"baud_rate":115200}}]}'
        ],
    },
    {
        "name": "uart_baud_rate_write_reply",
        "hex": "a5a5020480020100d3d3",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:22",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":1,"error_code":0}}]}'
        ],
    },
    {
        "name": "uart_baud_rate_read",
        "hex": "a5a50203010102537e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:32",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":1,"name":"uart_baud_rate","values":{"function":2}}]}'],
    },
    {
        "name": "uart_baud_rate_save",
        "hex": "a5a50203010103547f",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:46",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":1,"name":"uart_baud_rate","values":{"function":3}}]}'],
    },
    {
        "name": "uart_baud_rate_load",
        "hex": "a5a502030101045580",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:60",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":1,"name":"uart_baud_rate","values":{"function":4}}]}'],
    },
    {
        "name": "uart_baud_rate_default",
        "hex": "a5a502030101055681",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:74",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":1,"name":"uart_baud_rate","values":{"function":5}}]}'],
    },
    {
        "name": "uart_baud_rate_read_reply",
        "hex": "a5a5020a8002010081040001c20021a8",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:88",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":1,"error_code":0}},{"descriptor":129,"name":"uart_baud_rate_response","values":{"baud_rate":115200}}]}'
        ],
    },
    {
        "name": "uart_baud_rate_write_921600",
        "hex": "a5a50207010501000e10007847",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:106",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":1,"name":"uart_baud_rate","values":{"function":1,"baud_rate":921600}}]}'
        ],
    },
    {
        "name": "filter_write",
        "hex": "a5a502040302010258e1",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:121",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":1,"bandwidth":2}}]}'
        ],
    },
    {
        "name": "filter_write_reply",
        "hex": "a5a5020480020300d5d7",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:131",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":3,"error_code":0}}]}'
        ],
    },
    {
        "name": "filter_read",
        "hex": "a5a502030301025584",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:141",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":2}}]}'],
    },
    {
        "name": "filter_save",
        "hex": "a5a502030301035685",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:155",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":3}}]}'],
    },
    {
        "name": "filter_load",
        "hex": "a5a502030301045786",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:169",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":4}}]}'],
    },
    {
        "name": "filter_default",
        "hex": "a5a502030301055887",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:183",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":5}}]}'],
    },
    {
        "name": "filter_read_reply",
        "hex": "a5a50207800203008301025efb",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:197",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":3,"error_code":0}},{"descriptor":131,"name":"filter_response","values":{"bandwidth":2}}]}'
        ],
    },
    {
        "name": "filter_write_disabled",
        "hex": "a5a502040302010056df",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:215",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":1,"bandwidth":0}}]}'
        ],
    },
    {
        "name": "filter_save_with_placeholder",
        "hex": "a5a50204030203075fea",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:227",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":3,"name":"filter","values":{"function":3,"bandwidth":7}}]}'
        ],
    },
    {
        "name": "sample_rate_write",
        "hex": "a5a5020504030100126b56",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:242",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":4,"name":"sample_rate","values":{"function":1,"decimation":18}}]}'
        ],
    },
    {
        "name": "sample_rate_write_reply",
        "hex": "a5a5020480020400d6d9",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:254",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":4,"error_code":0}}]}'
        ],
    },
    {
        "name": "sample_rate_read",
        "hex": "a5a502030401025687",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:264",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":4,"name":"sample_rate","values":{"function":2}}]}'],
    },
    {
        "name": "sample_rate_save",
        "hex": "a5a502030401035788",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:278",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":4,"name":"sample_rate","values":{"function":3}}]}'],
    },
    {
        "name": "sample_rate_load",
        "hex": "a5a502030401045889",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:292",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":4,"name":"sample_rate","values":{"function":4}}]}'],
    },
    {
        "name": "sample_rate_default",
        "hex": "a5a50203040105598a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:306",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":4,"name":"sample_rate","values":{"function":5}}]}'],
    },
    {
        "name": "sample_rate_read_reply",
        "hex": "a5a5020880020400840200086873",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:320",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":4,"error_code":0}},{"descriptor":132,"name":"sample_rate_response","values":{"decimation":8}}]}'
        ],
    },
    {
        "name": "sample_rate_write_100hz",
        "hex": "a5a502050403010008614c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:338",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":4,"name":"sample_rate","values":{"function":1,"decimation":8}}]}'
        ],
    },
    {
        "name": "select_sensors_write",
        "hex": "a5a502060503010081825e2e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:352",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":1,"reserved":0,"sensors":[129,130]}}]}'
        ],
    },
    {
        "name": "select_sensors_write_reply",
        "hex": "a5a5020480020500d7db",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:367",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":5,"error_code":0}}]}'
        ],
    },
    {
        "name": "select_sensors_read",
        "hex": "a5a502030500025688",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:377",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":2}}]}'],
    },
    {
        "name": "select_sensors_save",
        "hex": "a5a502030500035789",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:392",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":3}}]}'],
    },
    {
        "name": "select_sensors_load",
        "hex": "a5a50203050004588a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:407",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":4}}]}'],
    },
    {
        "name": "select_sensors_default",
        "hex": "a5a50203050005598b",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:422",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":5}}]}'],
    },
    {
        "name": "select_sensors_read_reply",
        "hex": "a5a50208800205008502818265f9",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:437",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":5,"error_code":0}},{"descriptor":133,"name":"select_sensors_response","values":{"sensors":[129,130]}}]}'
        ],
    },
    {
        "name": "select_sensors_write_several",
        "hex": "a5a5020a050701008182868788847f37",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:457",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":5,"name":"select_sensors","values":{"function":1,"reserved":0,"sensors":[129,130,134,135,136,132]}}]}'
        ],
    },
    {
        "name": "get_internal_sample_rate_command",
        "hex": "a5a5020206005431",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:473",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":6,"name":"get_internal_sample_rate","values":{}}]}'],
    },
    {
        "name": "get_internal_sample_rate_reply",
        "hex": "a5a50208800206008602032087a5",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:483",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":6,"error_code":0}},{"descriptor":134,"name":"internal_sample_rate","values":{"rate":800}}]}'
        ],
    },
    {
        "name": "get_internal_sample_rate_reply_1000hz",
        "hex": "a5a5020880020600860203e84f6d",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:494",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":6,"error_code":0}},{"descriptor":134,"name":"internal_sample_rate","values":{"rate":1000}}]}'
        ],
    },
    {
        "name": "accel_range_write",
        "hex": "a5a50204070201025cf1",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:509",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":7,"name":"accel_range","values":{"function":1,"range":2}}]}'
        ],
    },
    {
        "name": "accel_range_write_reply",
        "hex": "a5a5020480020700d9df",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:523",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":7,"error_code":0}}]}'
        ],
    },
    {
        "name": "accel_range_read",
        "hex": "a5a502030701025990",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:533",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":7,"name":"accel_range","values":{"function":2}}]}'],
    },
    {
        "name": "accel_range_save",
        "hex": "a5a502030701035a91",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:547",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":7,"name":"accel_range","values":{"function":3}}]}'],
    },
    {
        "name": "accel_range_load",
        "hex": "a5a502030701045b92",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:561",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":7,"name":"accel_range","values":{"function":4}}]}'],
    },
    {
        "name": "accel_range_default",
        "hex": "a5a502030701055c93",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:575",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":7,"name":"accel_range","values":{"function":5}}]}'],
    },
    {
        "name": "accel_range_read_reply",
        "hex": "a5a5020780020700870102661b",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:589",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":7,"error_code":0}},{"descriptor":135,"name":"accel_range_response","values":{"range":2}}]}'
        ],
    },
    {
        "name": "gyro_range_write",
        "hex": "a5a50204080201025df5",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:607",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":8,"name":"gyro_range","values":{"function":1,"range":2}}]}'
        ],
    },
    {
        "name": "gyro_range_write_reply",
        "hex": "a5a5020480020800dae1",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:617",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":8,"error_code":0}}]}'
        ],
    },
    {
        "name": "gyro_range_read",
        "hex": "a5a502030801025a93",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:627",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":8,"name":"gyro_range","values":{"function":2}}]}'],
    },
    {
        "name": "gyro_range_save",
        "hex": "a5a502030801035b94",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:641",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":8,"name":"gyro_range","values":{"function":3}}]}'],
    },
    {
        "name": "gyro_range_load",
        "hex": "a5a502030801045c95",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:655",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":8,"name":"gyro_range","values":{"function":4}}]}'],
    },
    {
        "name": "gyro_range_default",
        "hex": "a5a502030801055d96",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:669",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":8,"name":"gyro_range","values":{"function":5}}]}'],
    },
    {
        "name": "gyro_range_read_reply",
        "hex": "a5a50207800208008801026823",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:683",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":8,"error_code":0}},{"descriptor":136,"name":"gyro_range_response","values":{"range":2}}]}'
        ],
    },
    {
        "name": "config_all_save",
        "hex": "a5a502030901035c97",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:701",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":9,"name":"config_all","values":{"function":3}}]}'],
    },
    {
        "name": "config_all_reply",
        "hex": "a5a5020480020900dbe3",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:711",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":9,"error_code":0}}]}'
        ],
    },
    {
        "name": "config_all_load",
        "hex": "a5a502030901045d98",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:721",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":9,"name":"config_all","values":{"function":4}}]}'],
    },
    {
        "name": "config_all_default",
        "hex": "a5a502030901055e99",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:734",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":9,"name":"config_all","values":{"function":5}}]}'],
    },
    {
        "name": "data_on_off_write",
        "hex": "a5a502040a0201015efc",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:748",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":10,"name":"data_on_off","values":{"function":1,"control":1}}]}'
        ],
    },
    {
        "name": "data_on_off_write_reply",
        "hex": "a5a5020480020a00dce5",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:758",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":10,"error_code":0}}]}'
        ],
    },
    {
        "name": "data_on_off_read",
        "hex": "a5a502030a01025c99",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:768",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":10,"name":"data_on_off","values":{"function":2}}]}'],
    },
    {
        "name": "data_on_off_save",
        "hex": "a5a502030a01035d9a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:782",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":10,"name":"data_on_off","values":{"function":3}}]}'],
    },
    {
        "name": "data_on_off_load",
        "hex": "a5a502030a01045e9b",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:796",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":10,"name":"data_on_off","values":{"function":4}}]}'],
    },
    {
        "name": "data_on_off_default",
        "hex": "a5a502030a01055f9c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:810",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":10,"name":"data_on_off","values":{"function":5}}]}'],
    },
    {
        "name": "data_on_off_read_reply",
        "hex": "a5a5020780020a008a01016b32",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:824",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":10,"error_code":0}},{"descriptor":138,"name":"data_on_off_response","values":{"control":1}}]}'
        ],
    },
    {
        "name": "data_on_off_write_off",
        "hex": "a5a502040a0201005dfb",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:841",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":10,"name":"data_on_off","values":{"function":1,"control":0}}]}'
        ],
    },
    {
        "name": "xtrig_on_off_write",
        "hex": "a5a502040b0201015f00",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:854",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":11,"name":"xtrig_on_off","values":{"function":1,"control":1}}]}'
        ],
    },
    {
        "name": "xtrig_on_off_write_reply",
        "hex": "a5a5020480020b00dde7",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:864",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":11,"error_code":0}}]}'
        ],
    },
    {
        "name": "xtrig_on_off_read",
        "hex": "a5a502030b01025d9c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:874",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":11,"name":"xtrig_on_off","values":{"function":2}}]}'],
    },
    {
        "name": "xtrig_on_off_save",
        "hex": "a5a502030b01035e9d",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:888",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":11,"name":"xtrig_on_off","values":{"function":3}}]}'],
    },
    {
        "name": "xtrig_on_off_load",
        "hex": "a5a502030b01045f9e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:902",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":11,"name":"xtrig_on_off","values":{"function":4}}]}'],
    },
    {
        "name": "xtrig_on_off_default",
        "hex": "a5a502030b0105609f",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:916",
        "expect": ['{"offset":0,"set":2,"fields":[{"descriptor":11,"name":"xtrig_on_off","values":{"function":5}}]}'],
    },
    {
        "name": "xtrig_on_off_read_reply",
        "hex": "a5a5020780020b008b01006c39",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:930",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":11,"error_code":0}},{"descriptor":139,"name":"xtrig_on_off_response","values":{"control":0}}]}'
        ],
    },
    {
        "name": "xtrig_on_off_write_off",
        "hex": "a5a502040b0201005eff",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:948",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":11,"name":"xtrig_on_off","values":{"function":1,"control":0}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_write",
        "hex": "a5a502050c0301818264f0",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:961",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":1,"sensors":[129,130]}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_write_reply",
        "hex": "a5a5020480020c00dee9",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:971",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":12,"error_code":0}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_read",
        "hex": "a5a502030c01025e9f",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:981",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":2}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_save",
        "hex": "a5a502030c01035fa0",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:995",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":3}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_load",
        "hex": "a5a502030c010460a1",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1009",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":4}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_default",
        "hex": "a5a502030c010561a2",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1023",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":5}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_read_reply",
        "hex": "a5a5020980020c008c03818289fe49",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1037",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":12,"error_code":0}},{"descriptor":140,"name":"select_sensors_rev_b_response","values":{"sensors":[129,130,137]}}]}'
        ],
    },
    {
        "name": "select_sensors_rev_b_write_all",
        "hex": "a5a5020c0c0a018182838485868788891ce0",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1055",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":1,"sensors":[129,130,131,132,133,134,135,136,137]}}]}'
        ],
    },
    {
        "name": "aux_accel_range_write",
        "hex": "a5a502040d020105650c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1069",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":13,"name":"aux_accel_range","values":{"function":1,"range":5}}]}'
        ],
    },
    {
        "name": "aux_accel_range_write_reply",
        "hex": "a5a5020480020d00dfeb",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1083",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":13,"error_code":0}}]}'
        ],
    },
    {
        "name": "aux_accel_range_read",
        "hex": "a5a502030d01025fa2",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1093",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":13,"name":"aux_accel_range","values":{"function":2}}]}'
        ],
    },
    {
        "name": "aux_accel_range_save",
        "hex": "a5a502030d010360a3",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1107",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":13,"name":"aux_accel_range","values":{"function":3}}]}'
        ],
    },
    {
        "name": "aux_accel_range_load",
        "hex": "a5a502030d010461a4",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1121",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":13,"name":"aux_accel_range","values":{"function":4}}]}'
        ],
    },
    {
        "name": "aux_accel_range_default",
        "hex": "a5a502030d010562a5",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1135",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":13,"name":"aux_accel_range","values":{"function":5}}]}'
        ],
    },
    {
        "name": "aux_accel_range_read_reply",
        "hex": "a5a5020780020d008d0105754e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_config.yaml:1149",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":13,"error_code":0}},{"descriptor":141,"name":"aux_accel_range_response","values":{"range":5}}]}'
        ],
    },
    {
        "name": "imu_data_default",
        "hex": "a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:11",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{"descriptor":130,"name":"scaled_gyro","values":{"gyro":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}'
        ],
    },
    {
        "name": "scaled_accel",
        "hex": "a5a5a20e810c37a7c5ac377ba8823f800065d61a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:26",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}'
        ],
    },
    {
        "name": "scaled_gyro",
        "hex": "a5a5a20e820c37a7c5ac377ba8823749539c2240",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:36",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":130,"name":"scaled_gyro","values":{"gyro":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}'
        ],
    },
    {
        "name": "scaled_mag",
        "hex": "a5a5a20e830c37a7c5ac377ba8823749539c234e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:46",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":131,"name":"scaled_mag","values":{"mag":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}'
        ],
    },
    {
        "name": "delta_theta",
        "hex": "a5a5a20e840c37a7c5ac377ba8823749539c245c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:56",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":132,"name":"delta_theta","values":{"delta_theta":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}'
        ],
    },
    {
        "name": "delta_velocity",
        "hex": "a5a5a20e850c37a7c5ac377ba8823749539c256a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:66",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":133,"name":"delta_velocity","values":{"delta_velocity":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}'
        ],
    },
    {
        "name": "scaled_aux_accel",
        "hex": "a5a5a20e890c37a7c5ac377ba8823f800065de8a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:76",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":137,"name":"scaled_aux_accel","values":{"accel":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}'
        ],
    },
    {
        "name": "scaled_pressure_published",
        "hex": "a5a5a2068604000003fd7cb4",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:89",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":134,"name":"scaled_pressure","values":{"pressure":1.4307257320756382e-42}}]}'
        ],
    },
    {
        "name": "scaled_pressure",
        "hex": "a5a5a2068604447f40007fbe",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:108",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":134,"name":"scaled_pressure","values":{"pressure":1021.0}}]}'
        ],
    },
    {
        "name": "scaled_temperature_published",
        "hex": "a5a5a20687040000001996d0",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:121",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":135,"name":"scaled_temperature","values":{"temperature":3.5032461608120427e-44}}]}'
        ],
    },
    {
        "name": "scaled_temperature",
        "hex": "a5a5a206870441c800008613",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:140",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":135,"name":"scaled_temperature","values":{"temperature":25.0}}]}'
        ],
    },
    {
        "name": "gps_correlated_time_published",
        "hex": "a5a5a20e880c410944c000000000072f00081a32",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mscip/imu_data.yaml:153",
        "expect": ['{"offset":0,"skipped":"a5a5a20e880c410944c000000000072f00081a32"}'],
    },
    {
        "name": "gps_correlated_time",
        "hex": "a5a5a20e880c410944c000000000072f00081a15",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:173",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":136,"name":"gps_correlated_time","values":{"seconds":207000.0,"week":1839,"flags":8}}]}'
        ],
    },
    {
        "name": "gps_correlated_time_not_set",
        "hex": "a5a5a20e880c4028b0a3d70a3d7100000004dc85",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:187",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":136,"name":"gps_correlated_time","values":{"seconds":12.345,"week":0,"flags":4}}]}'
        ],
    },
    {
        "name": "gps_correlated_time_set_and_pps",
        "hex": "a5a5a20e880c410944c00a3d70a4072f000370df",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:202",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":136,"name":"gps_correlated_time","values":{"seconds":207000.005,"week":1839,"flags":3}}]}'
        ],
    },
    {
        "name": "imu_data_gps_accel_temperature",
        "hex": "a5a5a222880c410944c000000000072f0000810c00000000bf0000003f800000870441c80000c52b",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:218",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":136,"name":"gps_correlated_time","values":{"seconds":207000.0,"week":1839,"flags":0}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[0.0,-0.5,1.0]}},{"descriptor":135,"name":"scaled_temperature","values":{"temperature":25.0}}]}'
        ],
    },
    {
        "name": "imu_data_all_fields",
        "hex": "a5a5a26e810c3c800000be8000003f800000820c3f000000bfc0000042b40000830c3e8000003d800000bf000000840c3a800000bb00000000000000850c3ba0000000000000bc2000008604447d50008704c2220000880c412274fffd70a3d709600001890cc0000000408000003e0000001011",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mscip/imu_data.yaml:235",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":129,"name":"scaled_accel","values":{"accel":[0.015625,-0.25,1.0]}},{"descriptor":130,"name":"scaled_gyro","values":{"gyro":[0.5,-1.5,90.0]}},{"descriptor":131,"name":"scaled_mag","values":{"mag":[0.25,0.0625,-0.5]}},{"descriptor":132,"name":"delta_theta","values":{"delta_theta":[0.0009765625,-0.001953125,0.0]}},{"descriptor":133,"name":"delta_velocity","values":{"delta_velocity":[0.0048828125,0.0,-0.009765625]}},{"descriptor":134,"name":"scaled_pressure","values":{"pressure":1013.25}},{"descriptor":135,"name":"scaled_temperature","values":{"temperature":-40.5}},{"descriptor":136,"name":"gps_correlated_time","values":{"seconds":604799.995,"week":2400,"flags":1}},{"descriptor":137,"name":"scaled_aux_accel","values":{"accel":[-2.0,4.0,0.125]}}]}'
        ],
    },
    {
        "name": "mscip_garbage_around_packets",
        "hex": "00ff13a5a5010202004f2555a5a5010480020200d3cfa5",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:8",
        "expect": [
            '{"offset":0,"skipped":"00ff13"}',
            '{"offset":3,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
            '{"offset":11,"skipped":"55"}',
            '{"offset":12,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":2,"error_code":0}}]}',
            '{"offset":22,"skipped":"a5"}',
        ],
    },
    {
        "name": "mscip_false_sync_running_past_the_end",
        "hex": "a5a50130a5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:28",
        "expect": [
            '{"offset":0,"skipped":"a5a50130"}',
            '{"offset":4,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "mscip_false_sync_bad_checksum_packet_inside",
        "hex": "a5a5010aa5a5010202004f2500000000",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:42",
        "expect": [
            '{"offset":0,"skipped":"a5a5010a"}',
            '{"offset":4,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
            '{"offset":12,"skipped":"00000000"}',
        ],
    },
    {
        "name": "mscip_extra_sync_byte",
        "hex": "a5a5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:58",
        "expect": [
            '{"offset":0,"skipped":"a5"}',
            '{"offset":1,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "mscip_packets_back_to_back",
        "hex": "a5a502050c0301818264f0a5a5020480020c00dee9a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:72",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"descriptor":12,"name":"select_sensors_rev_b","values":{"function":1,"sensors":[129,130]}}]}',
            '{"offset":11,"set":2,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":12,"error_code":0}}]}',
            '{"offset":21,"set":162,"fields":[{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{"descriptor":130,"name":"scaled_gyro","values":{"gyro":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}',
            '{"offset":55,"set":162,"fields":[{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{"descriptor":130,"name":"scaled_gyro","values":{"gyro":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}',
        ],
    },
    {
        "name": "mscip_mip_packet_in_mscip_stream",
        "hex": "a5a5010202004f25756501020201e0c6a5a5010480020200d3cf",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:98",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
            '{"offset":8,"skipped":"756501020201e0c6"}',
            '{"offset":16,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":2,"error_code":0}}]}',
        ],
    },
    {
        "name": "mscip_bad_checksum_then_valid",
        "hex": "a5a5010480020200d3cea5a5010480020200d3cf",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:116",
        "expect": [
            '{"offset":0,"skipped":"a5a5010480020200d3ce"}',
            '{"offset":10,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"command_code":2,"error_code":0}}]}',
        ],
    },
    {
        "name": "mscip_truncated_packet_at_end",
        "hex": "a5a50104800202",
        "device": None,
        "rejected": True,
        "where": "tests/streams/mscip/framing_and_fields.yaml:129",
        "expect": ['{"offset":0,"skipped":"a5a50104800202"}'],
    },
    {
        "name": "mscip_field_header_cut_short",
        "hex": "a5a50103020080d0f8",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:135",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}},{"trailing":"80","error":"field header at payload offset 2 needs 2 bytes, 1 left"}]}'
        ],
    },
    {
        "name": "mscip_field_size_overruns_payload",
        "hex": "a5a5010480030200d4d2",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:146",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"trailing":"80030200","error":"field length 3 at payload offset 0 overruns the payload (4 bytes left)"}]}'
        ],
    },
    {
        "name": "mscip_field_too_short_for_type",
        "hex": "a5a5a2048602447f3bb0",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:157",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":134,"data":"447f","error":"pressure: needs 4 bytes at offset 0, 2 left"}]}'
        ],
    },
    {
        "name": "mscip_field_with_trailing_bytes",
        "hex": "a5a50103020155a6cf",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:167",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"data":"55","error":"1 unexpected bytes at offset 0"}]}'
        ],
    },
    {
        "name": "mscip_message_list_with_half_entry",
        "hex": "a5a501058303010201dabd",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:177",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":131,"data":"010201","error":"messages: 3 bytes left at offset 0, not a multiple of 2"}]}'
        ],
    },
    {
        "name": "mscip_unknown_message_code",
        "hex": "a5a501020a005735",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:188",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":10,"data":"","error":"unknown descriptor"}]}'],
    },
    {
        "name": "mscip_ack_code_in_data_message",
        "hex": "a5a5a204800202007495",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:199",
        "expect": ['{"offset":0,"set":162,"fields":[{"descriptor":128,"data":"0200","error":"unknown descriptor"}]}'],
    },
    {
        "name": "mscip_unknown_message_type",
        "hex": "a5a5a30681043f8000003717",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:210",
        "expect": [
            '{"offset":0,"set":163,"fields":[{"descriptor":129,"data":"3f800000","error":"unknown descriptor set"}]}'
        ],
    },
    {
        "name": "mscip_select_sensors_rev_a_with_a_regular_size_byte",
        "hex": "a5a502060504010081825f33",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields.yaml:220",
        "expect": [
            '{"offset":0,"set":2,"fields":[{"trailing":"050401008182","error":"field length 4 at payload offset 0 overruns the payload (6 bytes left)"}]}'
        ],
    },
    {
        "name": "mscip_empty_stream",
        "hex": "",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:7",
        "expect": [],
    },
    {
        "name": "mscip_garbage_inside_packet",
        "hex": "a5a50102aabbcc02004f25a5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:11",
        "expect": [
            '{"offset":0,"skipped":"a5a50102aabbcc02004f25"}',
            '{"offset":11,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "mscip_sync_bytes_inside_a_valid_payload",
        "hex": "a5a5a2067e04a5a5a5a508f3a5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:26",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":126,"data":"a5a5a5a5","error":"unknown descriptor"}]}',
            '{"offset":12,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "mscip_false_sync_of_maximum_length",
        "hex": "a5a5a2ffa5a5010202004f25a5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:42",
        "expect": [
            '{"offset":0,"skipped":"a5a5a2ff"}',
            '{"offset":4,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
            '{"offset":12,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "mscip_longest_legal_packet",
        "hex": "a5a5a2ff810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf000000400000007e0100b03fa5a5010202004f25",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:59",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}},{"descriptor":126,"data":"00","error":"unknown descriptor"}]}',
            '{"offset":261,"set":1,"fields":[{"descriptor":2,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "mscip_empty_payloads",
        "hex": "a5a5a200ecc7a5a501004b85",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:103",
        "expect": ['{"offset":0,"set":162,"fields":[]}', '{"offset":6,"set":1,"fields":[]}'],
    },
    {
        "name": "mscip_zero_length_fields",
        "hex": "a5a5a21281007e00810c3f800000bf0000004000000048bd",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:112",
        "expect": [
            '{"offset":0,"set":162,"fields":[{"descriptor":129,"data":"","error":"accel[0]: needs 4 bytes at offset 0, 0 left"},{"descriptor":126,"data":"","error":"unknown descriptor"},{"descriptor":129,"name":"scaled_accel","values":{"accel":[1.0,-0.5,2.0]}}]}'
        ],
    },
    {
        "name": "mscip_unknown_command_set",
        "hex": "a5a555020200a375",
        "device": None,
        "rejected": False,
        "where": "tests/streams/mscip/framing_and_fields_more.yaml:125",
        "expect": ['{"offset":0,"set":85,"fields":[{"descriptor":2,"data":"","error":"unknown descriptor set"}]}'],
    },
]
