"""Tables of the library as pandas DataFrames, units kept in ``df.attrs["units"]``."""

import pandas as pd


def frame(table):
    """A run's table ({columns, units, values}) as a DataFrame with t as the first column."""
    df = pd.DataFrame(table["values"], columns=table["columns"])
    df.attrs["units"] = dict(zip(table["columns"], table["units"]))
    return df


def study_frame(table):
    """A study's table ({columns, units, data}) as a DataFrame, one row per point."""
    df = pd.DataFrame({name: table["data"][name] for name in table["columns"]}, columns=table["columns"])
    df.attrs["units"] = {c: u for c, u in zip(table["columns"], table["units"]) if u}
    return df
