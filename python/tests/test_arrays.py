"""Arrays in and out: round trips, and what the fitted arrays mean."""
import numpy as np
import pfdm
import pytest
from conftest import run_cli, scratch


def random_frames(seed=3, sizes=(40, 35, 50)):
    rng = np.random.default_rng(seed)
    positions = [rng.normal(scale=30.0, size=(n, 3)) for n in sizes]
    ids = [rng.permutation(100)[:n].astype(np.int64) for n in sizes]
    return positions, ids


def test_arrays_round_trip_through_a_sequence_and_its_csv():
    positions, ids = random_frames()
    sequence = pfdm.PointSequence(positions, ids, source="mine")
    assert len(sequence) == sequence.num_frames == 3
    assert sequence.source == "mine"
    back_positions, back_ids = sequence.to_arrays()
    for t in range(3):
        np.testing.assert_array_equal(back_positions[t], positions[t])
        np.testing.assert_array_equal(back_ids[t], ids[t])
        assert back_ids[t].dtype == np.int64
    path = scratch("round_trip") / "points.csv"
    sequence.write_csv(path)
    read = pfdm.read_points(path)
    assert read.source == str(path)
    for t in range(3):  # 17 digits: the CSV round-trips every double.
        np.testing.assert_array_equal(read.positions(t), positions[t])
        np.testing.assert_array_equal(read.ids(t), ids[t])
    np.testing.assert_array_equal(sequence.positions(-1), positions[2])


def test_one_array_of_frames_tracks_point_i_through_every_frame():
    block = np.arange(2 * 4 * 3, dtype=np.float32).reshape(2, 4, 3)
    sequence = pfdm.PointSequence(block)
    assert len(sequence) == 2
    np.testing.assert_array_equal(sequence.ids(1), [0, 1, 2, 3])
    np.testing.assert_array_equal(sequence.positions(1), block[1])
    assert sequence.positions(1).dtype == np.float64
    assert "2 frames, 8 points" in repr(sequence)


@pytest.fixture(scope="module")
def phantom_fit():
    points, truth = pfdm.simulate(frames=2, tags=400, seed=4)
    return pfdm.fit(points), truth


def test_material_points_and_residuals_agree_with_the_model(phantom_fit):
    fit, _ = phantom_fit
    for frame in fit.frames:
        material, points = frame.material, frame.points
        assert material.shape == (400, 2) and points.shape == (400, 3)
        u_min, u_max = frame.model.u_range
        assert np.all((material[:, 0] >= u_min) & (material[:, 0] <= u_max))
        assert np.all((material[:, 1] >= -np.pi) & (material[:, 1] <= np.pi))
        on_model = frame.evaluate(material[:, 0], material[:, 1])
        np.testing.assert_allclose(on_model - points, frame.residuals,
                                   atol=1e-9)
        rms = np.sqrt(np.mean(np.sum(frame.residuals**2, axis=1)))
        assert rms == pytest.approx(frame.stats["rms_mm"], rel=1e-12)
    # Tags keep their material point from frame 0 on.
    np.testing.assert_array_equal(fit.frames[1].material,
                                  fit.frames[0].material)


def test_evaluate_broadcasts_like_numpy(phantom_fit):
    fit, _ = phantom_fit
    model = fit.frames[1].model
    u = np.linspace(-1.2, 0.4, 4)[:, None]
    v = np.linspace(-3.0, 3.0, 5)
    grid = model.evaluate(u, v)
    assert grid.shape == (4, 5, 3)
    np.testing.assert_array_equal(grid[2, 3], model.evaluate(u[2, 0], v[3]))
    assert model.evaluate(0.1, 0.2).shape == (3,)
    np.testing.assert_array_equal(fit.frames[1].evaluate(u, v), grid)


def capped_volume_ml(vertices, faces):
    """Divergence theorem over the surface closed by a fan at its rim."""
    edges = {}
    for a, b, c in faces:
        for e in ((a, b), (b, c), (c, a)):
            edges[e] = edges.get(e, 0) + 1
    rim = [e for e in edges if (e[1], e[0]) not in edges]
    centroid = vertices[sorted({i for e in rim for i in e})].mean(axis=0)
    triangles = [vertices[f] for f in faces]
    triangles += [np.array([vertices[b], vertices[a], centroid]) for a, b in rim]
    triangles = np.array(triangles)
    signed = np.einsum("ij,ij->i", triangles[:, 0],
                       np.cross(triangles[:, 1], triangles[:, 2]))
    return abs(signed.sum()) / 6.0 / 1000.0


def test_surface_is_the_closed_models_triangulation(phantom_fit):
    fit, _ = phantom_fit
    frame = fit.frames[0]
    vertices, faces = frame.surface()
    # 33 rings of 48 but one vertex at the apex pole.
    assert vertices.shape == (32 * 48 + 1, 3) and vertices.dtype == np.float64
    assert faces.shape[1] == 3 and faces.dtype == np.int64
    assert faces.min() == 0 and faces.max() == len(vertices) - 1
    np.testing.assert_allclose(vertices[0], frame.evaluate(-np.pi / 2, -np.pi),
                               atol=1e-12)
    # The flat-lid volume of this coarse grid within 1 % of the fit's 97 x 128.
    volume = capped_volume_ml(vertices, faces)
    assert volume == pytest.approx(frame.clinical["midwall_volume_ml"],
                                   rel=0.01)
    assert frame.model.volume_ml() == pytest.approx(
        frame.clinical["midwall_volume_ml"], rel=1e-12)
    fine_vertices, _ = frame.surface(rings=65, meridians=96)
    assert len(fine_vertices) == 64 * 96 + 1


def test_model_pose_and_functions_are_arrays(phantom_fit):
    fit, truth = phantom_fit
    model = fit.frames[0].model
    assert model.name == "paper" and model.num_knots == 17
    assert model.functions.shape == (17, len(pfdm.FUNCTION_NAMES))
    assert model.knot_u[0] == pytest.approx(-np.pi / 2)
    assert model.knot_u[-1] == pytest.approx(np.pi / 6)
    np.testing.assert_array_equal(model.center, fit.frames[0].pose["center_mm"])
    np.testing.assert_array_equal(model.quaternion_wxyz,
                                  fit.frames[0].pose["quaternion_wxyz"])
    assert np.linalg.norm(model.quaternion_wxyz) == pytest.approx(1.0)
    assert truth[0].functions.shape == (17, len(pfdm.FUNCTION_NAMES))


def test_mesh_vertices_read_as_the_cli_reads_them():
    folder = scratch("meshes")
    meshes = folder / "obj"
    meshes.mkdir()
    rng = np.random.default_rng(5)
    frames = [rng.normal(size=(4, 3)) for _ in range(2)]
    for t, vertices in enumerate(frames):
        lines = ["v %.17g %.17g %.17g" % tuple(v) for v in vertices]
        lines += ["f 1 2 3", "f 1 3 4", "f 1 4 2"]  # Open at the base.
        (meshes / f"LV_{t:02d}.obj").write_text("\n".join(lines) + "\n")
    (meshes / "RV_00.obj").write_text("v 0 0 0\n")  # Filtered out.
    sequence = pfdm.read_mesh_points(meshes, mesh_filter="LV")
    assert len(sequence) == 2
    for t in range(2):
        np.testing.assert_array_equal(sequence.positions(t), frames[t])
        np.testing.assert_array_equal(sequence.ids(t), [0, 1, 2, 3])
    code, _, err = run_cli("mesh-points", "--mesh", meshes, "--mesh_filter",
                           "LV", "--out", folder / "points.csv")
    assert code == 0, err
    from_cli = pfdm.read_points(folder / "points.csv")
    for t in range(2):
        np.testing.assert_array_equal(from_cli.positions(t), frames[t])
    with pytest.raises(pfdm.InputError) as raised:
        pfdm.read_mesh_points(meshes, mesh_filter="LA")
    assert str(raised.value) == f"{meshes}: no .obj file matching 'LA'"
