"""Shared settings: hypothesis examples are bounded so that the whole suite stays within a few
seconds on two cores; no deadline (the machine is shared)."""
try:
    from hypothesis import HealthCheck, settings

    settings.register_profile("zdg", max_examples=60, deadline=None,
                              suppress_health_check=[HealthCheck.too_slow])
    settings.load_profile("zdg")
except ImportError:  # property tests skip themselves (pytest.importorskip)
    pass
