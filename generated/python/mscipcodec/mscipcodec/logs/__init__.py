"""The logs room of mscipcodec: what a user does with recorded logs (optional libraries).

`arrow` (the Arrow helpers, imported by the exporters and the dataset), `writers` (the CSV, JSON
and table writers), `export` (`mscipcodec export`), `info` (`mscipcodec info`), `plot`
(`mscipcodec plot`), `commands` (the command line of these user commands), `dataset` (the Parquet
dataset of a fleet's logs), `timebase` (GPS/UTC time of samples) and `query` (DuckDB over a
dataset). Imports the codec room (and the session room for model names); nothing imports it but
the command lines and the Spark job.
"""
