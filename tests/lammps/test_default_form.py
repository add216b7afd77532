"""Issue 40, point 23: the asperity law's default form is passive in LAMMPS too (docs/decisions.md
D12): a pair_coeff or fix wall/bounce that names no form is `asperity_form passive`, which creates no
energy (main's default, published, gave D12's -1.13)."""
import lammps_runs as L

ICE = dict(material="ice-bshp96", radius=0.01)
D12 = dict(model="viscoelastic", A=1e-6, friction=0.014142, asperity=1e-6)  # zeta0 = 2e-4 R_eff


def test_default_pair_coeff_is_the_passive_form():
    """D12's collision (g^N = 1 m/s, g^T = 0.01 m/s) naming no form equals `asperity_form passive`
    bit for bit, with |eps^T| <= 1 and bounce's default within the geometry's 1.5e-3 at this g^N
    (test_pair_bounce); the published form, named, gives eps^T < -1."""
    runs = {form: L.head_on(ICE, dict(D12, **({"asperity_form": form} if form else {})), 1.0,
                            steps_per_contact=1000, tangential_velocity=0.01)
            for form in ("", "passive", "published")}
    eps_t, ref = runs[""][1], runs[""][2]
    assert eps_t == runs["passive"][1]
    assert abs(eps_t) <= 1.0 and abs(eps_t - ref["cor_tangential"]) <= 2e-3, (eps_t, ref["cor_tangential"])
    assert runs["published"][1] < -1.0, runs["published"][1]


def test_default_wall_is_the_passive_form():
    """fix wall/bounce naming no form equals `asperity_form passive` bit for bit (a linear spring,
    g^T below the first break) and differs from the published form."""
    eps = {form: L.wall_collision(ICE, dict(D12, **({"asperity_form": form} if form else {})), 0.1, 1000,
                                  tangential_velocity=0.001)[1]
           for form in ("", "passive", "published")}
    assert eps[""] == eps["passive"]
    assert abs(eps[""] - eps["published"]) > 1e-3, eps

