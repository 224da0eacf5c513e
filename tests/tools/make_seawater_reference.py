#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Write tests/data/seawater_reference.csv: TEOS-10 values from Debian's
python3-gsw (which wraps GSW-C) for test_seawater.cpp to check the C++
seawater functions against.

The grid spans fresh-ish to salty water, cold to warm, 0 to 1000 dbar, and
includes Baltic-like (SP 7, 5-17 degC) and North Sea (SP 34.5) water. Each
point is set by SP, t, p; its conductivity comes from gsw.C_from_SP, so the
C++ side gets a realistic (C, t, p) triple. Points colder than the freezing
temperature, which are not liquid water, are left out. The column in_funnel
says whether a point is inside the range of the 75-term density polynomial as
seawater.hpp documents it (GSW's gsw_infunnel with -3 degC for its freezing
bound); outside it, the C++ density must be NaN.

Usage: /usr/bin/python3 tests/tools/make_seawater_reference.py [OUT.csv]
"""
import os
import sys

import gsw
import numpy as np

SP_VALUES = [0.5, 2.0, 4.0, 7.0, 10.0, 15.0, 20.0, 25.0, 30.0, 34.5, 35.5, 38.0, 40.0]
T_VALUES_C = [-1.5, 0.0, 2.0, 5.0, 8.0, 11.0, 14.0, 17.0, 21.0, 26.0, 31.0]
P_VALUES_DBAR = [0.0, 10.0, 50.0, 200.0, 500.0, 1000.0]

COLUMNS = ["C_S_m", "t_C", "p_dbar", "SP", "SA_g_kg", "pt0_C", "CT_C", "rho_kg_m3", "in_funnel"]


def in_funnel(sa, ct, p):
    """The density range of seawater.hpp, written independently of the C++."""
    inside = (sa >= 0) & (sa <= 42) & (ct >= -3) & (ct <= 40) & (p >= 0) & (p <= 8000)
    mid = (p > 500) & (p < 6500)
    inside &= ~(mid & ((sa < p * 5e-3 - 2.5) | (ct > 31.66666666666667 - p * 3.333333333333334e-3)))
    inside &= ~((p >= 6500) & ((sa < 30) | (ct > 10)))
    return inside


def rows():
    sp, t, p = (a.ravel() for a in np.meshgrid(SP_VALUES, T_VALUES_C, P_VALUES_DBAR, indexing="ij"))
    # Conductivity in S/m as the C++ side takes it; gsw works in mS/cm.
    c_s_m = gsw.C_from_SP(sp, t, p) / 10.0
    # The reference values come from what the C++ code will be given, (C, t, p),
    # not from the SP the grid was drawn with.
    sp_ref = gsw.SP_from_C(c_s_m * 10.0, t, p)
    sa = gsw.SR_from_SP(sp_ref)
    pt0 = gsw.pt0_from_t(sa, t, p)
    ct = gsw.CT_from_t(sa, t, p)
    rho = gsw.rho(sa, ct, p)
    funnel = in_funnel(sa, ct, p).astype(float)
    liquid = t >= gsw.t_freezing(sa, p, 0.0)
    columns = (c_s_m, t, p, sp_ref, sa, pt0, ct, rho, funnel)
    yield from zip(*(column[liquid] for column in columns))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "data", "seawater_reference.csv")
    n = 0
    with open(out, "w") as f:
        f.write(f"# TEOS-10 reference values from python3-gsw {gsw.__version__}; "
                "written by tests/tools/make_seawater_reference.py, do not edit.\n")
        f.write("# SA is Reference Salinity (gsw.SR_from_SP); rho = gsw.rho(SA, CT, p).\n")
        f.write(",".join(COLUMNS) + "\n")
        for values in rows():
            # repr() round-trips a double exactly.
            f.write(",".join(repr(float(v)) for v in values[:-1]) + f",{int(values[-1])}\n")
            n += 1
    print(f"wrote {n} rows to {os.path.normpath(out)}")


if __name__ == "__main__":
    main()
