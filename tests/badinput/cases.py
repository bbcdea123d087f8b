"""The bad-input suite of ESPH: a valid small base scene and one-change cases against it.

The base scene: two touching iron blocks of 4 x 4 x 4 particles (spacing 0.1 mm, h = 1.3
spacings), bodies 1 and 2, contact solid with generated boundary particles, block A moving
at 50 m/s into block B, 20 steps (contact from the first step). Each case changes one
thing (a line replaced, removed, added or moved) and states its outcome:

  error:WORD    LAMMPS stops with an ERROR whose message contains WORD
  warning:WORD  the run completes with finite thermo and a WARNING containing WORD
  onewarning:WORD  the same, and no other new WARNING (one cause, one message)
  same          the run completes without a new warning and its thermo equals the base's
                (the change is legal and must not change the answer)
  runs          the run completes without a new warning and with finite thermo (legal
                input that changes the physics: a different kernel, EOS, option)

Cases with np 2 run on two MPI ranks and must give the same outcome (and, for errors,
the same message as on one rank: errors are collective).

Operations on the base (by line key): R(key, line) replace, D(key) delete,
A(key, line) insert after, B(key, line) insert before, M(key, before) move the line
before another, K(key, text) append text to the line.

What is accepted (legal input that runs) and why:
  * the ESPH styles in any order the docs allow (fix before pair_style, all fixes first):
    the same state fixes are made whichever style comes first, the answer is the same
  * units lj and cgs with SI numbers: no conversion factors, the same numbers
  * units metal and real with SI numbers: another scene (the numbers are read in those
    units), which runs
  * atom styles with per-atom mass (sphere) or without (charge, full): the package adds
    rmass when missing; boundary particles of another atom type; no atom map
  * a second fix esph/boundary on the same group: it finds the existing boundary
    particles and reuses them; velocity set before fix esph/boundary: boundary
    particles take their body's velocity at setup anyway
  * options that change the physics (kernel wendland, linear EOS, heat, hvar, artstress,
    xsph, gradient plain, bonet/lok or torquefree, contact paper/off, newton off, yield, shear 0,
    fix esph/integrate scheme staggered): they run
  * fix esph/integrate move no with fix move: the documented way to prescribe motion
  * a rigid type (pair_coeff ... rigid yes) left out of the group of fix esph/integrate
"""

BASE = [
    ("units", "units si"),
    ("atom_style", "atom_style atomic"),
    ("atom_modify", "atom_modify map array"),
    ("boundary", "boundary f f f"),
    ("box", "region box block -0.0006 0.0006 -0.0004 0.0004 -0.0004 0.0004"),
    ("create_box", "create_box 2 box"),
    ("lattice", "lattice sc 1e-4 origin 0.5 0.5 0.5"),
    ("ra", "region ra block -0.0004 0 -0.0002 0.0002 -0.0002 0.0002 units box"),
    ("rb", "region rb block 0 0.0004 -0.0002 0.0002 -0.0002 0.0002 units box"),
    ("ca", "create_atoms 1 region ra"),
    ("cb", "create_atoms 2 region rb"),
    ("ga", "group a region ra"),
    ("gb", "group b region rb"),
    ("pair", "pair_style esph/solid 1.3e-4"),
    ("coeff", "pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69"),
    ("fix_int", "fix int all esph/integrate"),
    ("timestep", "timestep 5e-9"),
    ("mass", "set group all mass 7.85e-9"),
    ("body_a", "set group a i_esph_body 1"),
    ("body_b", "set group b i_esph_body 2"),
    ("fix_bnd", "fix bnd all esph/boundary spacing 1e-4"),
    ("velocity", "velocity a set 50 0 0 units box"),
    ("neighbor", "neighbor 2e-5 bin"),
    ("ke", "compute ke all ke"),
    ("thermo_style", "thermo_style custom step c_ke pe f_int[1] f_int[2] f_int[8]"),
    ("thermo_modify", "thermo_modify format float %.15g"),
    ("thermo", "thermo 5"),
    ("run", "run 20"),
]


def R(key, line):
    return ("R", key, line)


def D(key):
    return ("D", key, None)


def A(key, line):
    return ("A", key, line)


def B(key, line):
    return ("B", key, line)


def M(key, before):
    return ("M", key, before)


def K(key, text):
    return ("K", key, text)


PS = "pair_style esph/solid 1.3e-4 "
PC = "pair_coeff * * rho0 7850 shear 80e9 "
MG = "eos mie/gruneisen 3574 1.92 1.69"
FB = "fix bnd all esph/boundary "
# a site of block A's lattice (cell centres at odd multiples of 0.05 mm)
SITE = "-0.00005 0.00005 0.00005"

# write a restart file at the end of the base run and read it back (a case adds the rest)
RESTART = [A("run", "write_restart base.restart"), A("run", "clear"),
           A("run", "read_restart base.restart")]

# name, change, expected[, np]
CASES = [
    # ---------------- pair_style esph/solid ----------------
    ("ps_h_missing", [R("pair", "pair_style esph/solid")], "error:missing argument"),
    ("ps_h_negative", [R("pair", "pair_style esph/solid -1.3e-4")], "error:must be > 0"),
    ("ps_h_zero", [R("pair", "pair_style esph/solid 0")], "error:must be > 0"),
    ("ps_h_text", [R("pair", "pair_style esph/solid big")], "error:Expected floating point"),
    ("ps_unknown_keyword", [K("pair", " bogus 1")], "error:keyword: bogus"),
    ("ps_kernel_missing", [K("pair", " kernel")], "error:missing argument"),
    ("ps_kernel_unknown", [K("pair", " kernel quintic")], "error:quintic"),
    ("ps_kernel_wendland", [K("pair", " kernel wendland")], "runs"),
    ("ps_kernel_cubic", [K("pair", " kernel cubic")], "same"),
    ("ps_dimension_missing", [K("pair", " dimension")], "error:missing argument"),
    ("ps_dimension_zero", [K("pair", " dimension 0")], "error:dimension must be 1"),
    ("ps_dimension_four", [K("pair", " dimension 4")], "error:dimension must be 1"),
    ("ps_dimension_text", [K("pair", " dimension three")], "error:Expected integer"),
    ("ps_dimension_1_on_3d", [K("pair", " dimension 1")], "error:a 1D kernel needs"),
    ("ps_dimension_2_on_3d", [K("pair", " dimension 2")], "error:a 2D kernel needs"),
    ("ps_dimension_3", [K("pair", " dimension 3")], "same"),
    ("ps_visc_missing", [K("pair", " visc 1 1")], "error:missing argument"),
    ("ps_visc_alpha_negative", [K("pair", " visc -1 1 0.1")], "error:must be >= 0"),
    ("ps_visc_beta_negative", [K("pair", " visc 1 -1 0.1")], "error:must be >= 0"),
    ("ps_visc_eps_zero", [K("pair", " visc 1 1 0")], "error:epsilon must be > 0"),
    ("ps_visc_text", [K("pair", " visc one 1 0.1")], "error:Expected floating point"),
    ("ps_visc_default", [K("pair", " visc 1 1 0.1")], "same"),
    ("ps_visc_off", [K("pair", " visc 0 0 0.1")], "runs"),
    ("ps_heat_missing", [K("pair", " heat 0.1")], "error:missing argument"),
    ("ps_heat_negative", [K("pair", " heat -0.1 1")], "error:must be >= 0"),
    ("ps_heat_on", [K("pair", " heat 0.1 1.0")], "runs"),
    ("ps_hvar_missing", [K("pair", " hvar")], "error:missing argument"),
    ("ps_hvar_below_one", [K("pair", " hvar 0.5")], "error:(>= 1)"),
    ("ps_hvar_text", [K("pair", " hvar x")], "error:Expected floating point"),
    ("ps_hvar_on", [K("pair", " hvar 1.5")], "runs"),
    # h and h x hvar against the particle spacing of fix esph/boundary (1 to 2 is usual)
    ("ps_h_huge", [R("pair", "pair_style esph/solid 0.13")], "error:smoothing length h = 0.13"),
    ("ps_hvar_huge", [K("pair", " hvar 1000")], "error:hvar 1000: the smoothing length may grow"),
    ("ps_h_four_spacings", [R("pair", "pair_style esph/solid 4e-4")],
     "warning:1 to 2 spacings is usual"),
    ("ps_h_two_spacings_hvar_two", [R("pair", "pair_style esph/solid 2e-4 hvar 2")], "runs"),
    # the vector pass: a boolean; a full list too large for neigh_modify one: scalar, warned
    ("ps_simd_missing", [K("pair", " simd")], "error:missing argument"),
    ("ps_simd_unknown", [K("pair", " simd maybe")], "error:maybe"),
    ("ps_simd_no", [K("pair", " simd no")], "runs"),
    ("ps_simd_h_large", [R("pair", "pair_style esph/solid 4e-4")],
     "warning:would exceed neigh_modify one 2000"),
    ("ps_contact_missing", [K("pair", " contact")], "error:missing argument"),
    ("ps_contact_unknown", [K("pair", " contact maybe")], "error:maybe"),
    ("ps_contact_solid", [K("pair", " contact solid")], "same"),
    ("ps_contact_paper", [K("pair", " contact paper")], "runs"),
    ("ps_contact_off_no_boundary", [K("pair", " contact off"), D("fix_bnd")], "runs"),
    ("ps_gradient_unknown", [K("pair", " gradient smooth")], "error:smooth"),
    ("ps_gradient_corrected", [K("pair", " gradient corrected")], "same"),
    ("ps_gradient_plain", [K("pair", " gradient plain")], "runs"),
    ("ps_gradient_bonetlok", [K("pair", " gradient bonet/lok")], "runs"),
    ("ps_gradient_bonet", [K("pair", " gradient bonet")], "error:bonet"),
    ("ps_gradient_torquefree", [K("pair", " gradient torquefree")], "runs"),
    ("ps_artstress_missing", [K("pair", " artstress 0.3 4")], "error:missing argument"),
    ("ps_artstress_negative", [K("pair", " artstress -0.3 4 1e-4")], "error:epsilon must be >= 0"),
    ("ps_artstress_n_zero", [K("pair", " artstress 0.3 0 1e-4")], "error:n must be >= 1"),
    ("ps_artstress_n_huge", [K("pair", " artstress 0.3 1000 1e-4")], "warning:a hard core"),
    ("ps_artstress_n_8", [K("pair", " artstress 0.3 8 1e-4")], "runs"),
    ("ps_artstress_n_text", [K("pair", " artstress 0.3 four 1e-4")], "error:Expected integer"),
    ("ps_artstress_dp_zero", [K("pair", " artstress 0.3 4 0")], "error:dp must be > 0"),
    ("ps_artstress_dp_too_big", [K("pair", " artstress 0.3 4 3e-4")], "error:below the kernel"),
    ("ps_artstress_on", [K("pair", " artstress 0.3 4 1e-4")], "runs"),
    ("ps_artstress_dp_small", [K("pair", " artstress 0.3 4 3e-5")], "warning:dp is the particle spacing"),
    ("ps_artstress_zero_is_off", [K("pair", " artstress 0 4 1e-4")], "same"),
    ("ps_xsph_missing", [K("pair", " xsph")], "error:missing argument"),
    ("ps_xsph_above_one", [K("pair", " xsph 1.5")], "error:[0, 1]"),
    ("ps_xsph_negative", [K("pair", " xsph -0.5")], "error:[0, 1]"),
    ("ps_xsph_on", [K("pair", " xsph 0.5")], "runs"),
    # the per-type mass command instead of set ... mass: ESPH keeps per-particle masses, and
    # the error on the zero masses says so
    ("ps_mass_command", [R("mass", "mass * 7.85e-9")],
     "error:the mass command sets masses per type, which ESPH does not use", 2),
    # h below half the spacing: the kernel (2 h) reaches no neighbour, the bodies fall apart
    # into free particles (a user sweep: first contact 10 % late, rebound 36 instead of 4.5
    # m/s, silently); 0.7 spacings: only the nearest neighbours
    ("ps_h_no_neighbours", [R("pair", "pair_style esph/solid 0.4e-4")],
     "error:so no particle has a neighbour", 2),
    ("ps_h_small", [R("pair", "pair_style esph/solid 0.7e-4")],
     "warning:a particle sees only its nearest neighbours"),
    ("ps_gaptol_missing", [K("pair", " gap/tol")], "error:missing argument"),
    ("ps_gaptol_negative", [K("pair", " gap/tol -1")], "error:gap/tol must be >= 0"),
    ("ps_gaptol_text", [K("pair", " gap/tol tiny")], "error:Expected floating point"),
    ("ps_gaptol_default", [K("pair", " gap/tol 0.05")], "same"),
    ("ps_onset_missing", [K("pair", " onset")], "error:missing argument"),
    ("ps_onset_negative", [K("pair", " onset -1")], "error:onset must be >= 0"),
    ("ps_onset_text", [K("pair", " onset slow")], "error:Expected integer"),
    ("ps_onset_default", [K("pair", " onset 5")], "same"),
    ("ps_onset_huge", [K("pair", " onset 1000")], "warning:never couples fully"),
    ("ps_onset_20", [K("pair", " onset 20")], "runs"),
    ("ps_gaptol_huge", [K("pair", " gap/tol 1e300")], "warning:visibly apart"),
    ("ps_gaptol_one", [K("pair", " gap/tol 1")], "runs"),
    # a body added between runs while the old boundary particles remain: the fix uses them
    ("bf_body_added_reused",
     [A("run", "unfix bnd"), A("run", "region rc block 0.0004 0.0006 -0.0001 0.0001 -0.0001 0.0001 units box"),
      A("run", "create_atoms 2 region rc"), A("run", "group c region rc"),
      A("run", "set group c mass 7.85e-9"), A("run", "set group c i_esph_body 3"),
      A("run", "fix bnd all esph/boundary spacing 1e-4"), A("run", "run 2")],
     "error:so the surface has holes there"),
    # (group c also holds four of block b's boundary particles, which the set mass makes real:
    # b's surface has holes; with a group of the new atoms only, the new body has none)
    ("bf_body_added_reused_only_new",
     [A("run", "unfix bnd"), A("run", "region rc block 0.0004 0.0006 -0.0001 0.0001 -0.0001 0.0001 units box"),
      A("run", "variable nb atom mass>0.0||mass<0.0"), A("run", "group old variable nb"),
      A("run", "group zm subtract all old"),
      A("run", "create_atoms 2 region rc"), A("run", "group c subtract all old zm"),
      A("run", "set group c mass 7.85e-9"), A("run", "set group c i_esph_body 3"),
      A("run", "fix bnd all esph/boundary spacing 1e-4"), A("run", "run 2")],
     "error:a body added since they were made"),
    # masses and densities that do not fit the particle spacing or rho0 (warnings at setup)
    ("pc_mass_heavy_body", [R("mass", "set group all mass 7.85e-9"), A("mass", "set group b mass 3.14e-8")],
     "warning:have a reference volume m / rho0 of 4 to 4 x"),
    # aluminium given iron's particle mass: a material 2.9 times stiffer than its rho0 says,
    # which the CFL step does not see (the run gained energy and blew up, silently at first)
    ("pc_mass_of_other_material",
     [R("coeff", "pair_coeff 1 1 rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69"),
      A("coeff", "pair_coeff 2 2 rho0 2703 shear 27.6e9 eos mie/gruneisen 5240 1.40 1.97")],
     "warning:have a reference volume m / rho0 of 2.9 to 2.9 x"),
    # neighbor exclusions remove the pairs of the contact (a block passed through the other)
    ("nb_exclude_type", [A("neighbor", "neigh_modify exclude type 1 2")],
     "warning:do not interact at all"),
    # pair_modify options that mean nothing to the pair style
    ("pc_pair_modify_shift", [A("coeff", "pair_modify shift yes")], "warning:has no effect"),
    ("pc_pair_modify_tail", [A("coeff", "pair_modify tail yes")], "warning:has no effect"),
    # rerun as the first run: the state was never set up by a run (density 0)
    ("rr_rerun_before_any_run",
     [R("run", "write_dump all custom rr.dump id x y z vx vy vz"),
      A("run", "rerun rr.dump dump x y z vx vy vz")],
     "error:give run 0 first"),
    ("pc_rho0_changed_between_runs",
     [A("run", "pair_coeff * * rho0 2700 shear 26e9 eos linear 75e9"), A("run", "run 2")],
     "warning:x the rho0 of their type"),
    # the gate's keywords under the rules that have no gate
    ("ps_gaptol_paper", [K("pair", " contact paper gap/tol 0.5")],
     "warning:gap/tol applies to contact solid only"),
    ("ps_onset_off", [K("pair", " contact off onset 50")], "warning:onset applies to contact solid only"),
    ("ps_cnormal_missing", [K("pair", " contact/normal")], "error:missing argument"),
    ("ps_cnormal_bogus", [K("pair", " contact/normal sharp")], "error:contact/normal must be cone or mean"),
    ("ps_cnormal_mean", [K("pair", " contact/normal mean")], "same"),
    ("ps_cgap_missing", [K("pair", " contact/gap")], "error:missing argument"),
    ("ps_cgap_bogus", [K("pair", " contact/gap tangent")], "error:contact/gap must be touch, projection or plane"),
    ("ps_cgap_projection", [K("pair", " contact/gap projection")], "same"),
    ("ps_cgap_plane", [K("pair", " contact/gap plane")], "runs"),
    ("ps_cgap_off", [K("pair", " contact off contact/gap plane")],
     "warning:contact/gap applies to contact solid only"),
    ("ps_cnormal_cone", [K("pair", " contact/normal cone")], "runs"),
    ("ps_cnormal_cone_friction", [K("pair", " friction 0.2 contact/normal cone")], "runs"),
    ("ps_cnormal_cone_np2", [K("pair", " contact/normal cone")], "runs", 2),
    ("ps_cnormal_cone_paper", [K("pair", " contact paper contact/normal cone")],
     "warning:contact/normal cone"),
    ("ps_couple_missing", [K("pair", " contact/couple")], "error:missing argument"),
    ("ps_couple_bogus", [K("pair", " contact/couple maybe")], "error:Expected boolean"),
    ("ps_couple_no", [K("pair", " contact/couple no")], "same"),
    ("ps_couple_yes", [K("pair", " contact/couple yes")], "runs"),
    ("ps_couple_np2", [K("pair", " contact/couple yes gradient bonet/lok")], "runs", 2),
    ("ps_couple_friction", [K("pair", " contact/couple yes friction 0.3")], "runs"),
    ("ps_couple_contact_off", [K("pair", " contact off contact/couple yes")],
     "warning:contact/couple has no effect with contact off"),
    ("ps_friction_missing", [K("pair", " friction")], "error:missing argument"),
    ("ps_friction_negative", [K("pair", " friction -0.1")], "error:friction coefficient must be"),
    ("ps_friction_text", [K("pair", " friction rough")], "error:Expected floating point"),
    ("ps_friction_default", [K("pair", " friction 0")], "same"),
    ("ps_vswitch_missing", [K("pair", " visc/switch 0.1")], "error:missing argument"),
    ("ps_vswitch_zero", [K("pair", " visc/switch 0 0.2")], "error:alpha_min must be > 0"),
    ("ps_vswitch_l", [K("pair", " visc/switch 0.1 2")], "error:l must be in (0, 1]"),
    ("ps_vswitch_text", [K("pair", " visc/switch low 0.2")], "error:Expected floating point"),
    ("ps_vswitch_above", [K("pair", " visc/switch 2 0.2")], "error:must not exceed the visc alpha"),
    ("ps_vswitch_off", [K("pair", " visc/switch off")], "same"),
    ("ps_recon_missing", [K("pair", " visc/recon")], "error:missing argument"),
    ("ps_recon_bogus", [K("pair", " visc/recon superbee")], "error:must be vanleer, minmod or off, got superbee"),
    ("ps_recon_off", [K("pair", " visc/recon off")], "runs"),
    ("ps_recon_vanleer", [K("pair", " visc/recon vanleer")], "same"),
    # the default reconstruction without a viscosity is switched off without a word
    ("ps_recon_default_no_visc", [K("pair", " visc 0 0 0.1")], "runs"),
    ("ps_recon_minmod_np2", [K("pair", " visc/recon minmod")], "runs", 2),
    ("ps_recon_no_visc", [K("pair", " visc 0 0 0.1 visc/recon vanleer")], "warning:visc/recon with visc alpha and beta 0"),
    ("ps_recon_fix_first", [K("pair", " visc/recon vanleer"), M("fix_int", "pair")], "runs"),
    # the reconstruction acts only in types without a yield stress: with none such it is
    # off (no per-atom rates), silently by default, with a warning if given
    ("ps_recon_default_all_yield", [K("coeff", " yield 2e8")], "runs"),
    ("ps_recon_all_yield", [K("pair", " visc/recon vanleer"), K("coeff", " yield 2e8")],
     "warning:visc/recon has no effect: no real particle is of a deformable type"),
    # a type without a yield stress that holds boundary particles only does not count
    ("ps_recon_bnd_type_elastic", [R("create_box", "create_box 3 box"), K("pair", " visc/recon vanleer"),
                                   K("coeff", " yield 2e8"),
                                   A("coeff", (PC + MG).replace("* *", "3 3")),
                                   R("fix_bnd", FB + "spacing 1e-4 type 3")],
     "warning:visc/recon has no effect: no real particle is of a deformable type"),
    ("ps_recon_off_all_yield", [K("pair", " visc/recon off"), K("coeff", " yield 2e8")], "runs"),
    ("ps_recon_one_yield", [K("pair", " visc/recon minmod"),
                            A("coeff", (PC + MG).replace("* *", "2 2") + " yield 2e8")], "runs"),
    # ---------------- pair_coeff ----------------
    ("pc_missing", [D("coeff")], "error:coeffs are not set"),
    ("pc_one_type_only", [R("coeff", "pair_coeff 1 1 rho0 7850 shear 80e9 " + MG)],
     "error:coeffs are not set"),
    ("pc_cross_types", [R("coeff", "pair_coeff 1 2 rho0 7850 shear 80e9 " + MG)],
     "error:per atom type"),
    ("pc_type_out_of_range", [R("coeff", "pair_coeff 3 3 rho0 7850 shear 80e9 " + MG)],
     "error:out of bounds"),
    ("pc_no_keywords", [R("coeff", "pair_coeff * *")], "error:missing the rho0"),
    ("pc_rho0_missing", [R("coeff", "pair_coeff * * shear 80e9 " + MG)], "error:missing the rho0"),
    ("pc_rho0_negative", [R("coeff", "pair_coeff * * rho0 -7850 shear 80e9 " + MG)],
     "error:rho0 must be > 0"),
    ("pc_rho0_zero", [R("coeff", "pair_coeff * * rho0 0 shear 80e9 " + MG)],
     "error:rho0 must be > 0"),
    ("pc_rho0_text", [R("coeff", "pair_coeff * * rho0 iron shear 80e9 " + MG)],
     "error:Expected floating point"),
    ("pc_rho0_no_value", [R("coeff", "pair_coeff * * shear 80e9 " + MG + " rho0")],
     "error:missing argument"),
    ("pc_shear_missing", [R("coeff", "pair_coeff * * rho0 7850 " + MG)], "error:missing the shear"),
    ("pc_shear_negative", [R("coeff", "pair_coeff * * rho0 7850 shear -80e9 " + MG)],
     "error:shear modulus must be >= 0"),
    ("pc_shear_zero", [R("coeff", "pair_coeff * * rho0 7850 shear 0 " + MG)], "runs"),
    ("pc_eos_missing", [R("coeff", PC)], "error:missing the eos"),
    ("pc_eos_unknown", [R("coeff", PC + "eos tillotson 1")], "error:tillotson"),
    ("pc_eos_no_name", [R("coeff", PC + "eos")], "error:missing argument"),
    ("pc_linear_missing_K", [R("coeff", PC + "eos linear")], "error:missing argument"),
    ("pc_linear_K_zero", [R("coeff", PC + "eos linear 0")], "error:bulk modulus must be > 0"),
    ("pc_linear_K_text", [R("coeff", PC + "eos linear stiff")], "error:Expected floating point"),
    ("pc_linear", [R("coeff", PC + "eos linear 1.0e11")], "runs"),
    ("pc_mg_missing", [R("coeff", PC + "eos mie/gruneisen 3574 1.92")], "error:missing argument"),
    ("pc_mg_c0_negative", [R("coeff", PC + "eos mie/gruneisen -3574 1.92 1.69")],
     "error:c0 must be > 0"),
    ("pc_mg_s_negative", [R("coeff", PC + "eos mie/gruneisen 3574 -1.92 1.69")],
     "error:s must be >= 0"),
    ("pc_mg_gamma_negative", [R("coeff", PC + "eos mie/gruneisen 3574 1.92 -1.69")],
     "error:gamma0 must be >= 0"),
    ("pc_yield_negative", [K("coeff", " yield -1")], "error:yield stress must be >= 0"),
    ("pc_yield_on", [K("coeff", " yield 2e8")], "runs"),
    ("pc_yield_zero_is_elastic", [K("coeff", " yield 0")], "same"),
    ("pc_hardening_without_yield", [K("coeff", " hardening 1e9")], "error:needs a yield stress"),
    ("pc_hardening_negative", [K("coeff", " yield 2e8 hardening -1")],
     "error:hardening modulus must be >= 0"),
    ("pc_unknown_keyword", [K("coeff", " young 200e9")], "error:keyword: young"),
    ("pc_rigid_no_value", [K("coeff", " rigid")], "error:missing argument"),
    ("pc_rigid_text", [K("coeff", " rigid maybe")], "error:Expected boolean"),
    ("pc_rigid_no_is_default", [K("coeff", " rigid no")], "same"),
    ("pc_rigid_in_group", [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes")],
     "error:is in the group of fix esph/integrate", 2),
    ("pc_rigid_outside_group", [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG +
                                  " rigid yes"), R("fix_int", "fix int a esph/integrate")], "runs"),
    ("pc_rigid_velocity_unmoved",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"), A("velocity", "velocity b set -20 0 0 units box")],
     "warning:has a velocity but no fix moves it"),
    # a deformable block left out of the group of fix esph/integrate, with a velocity no fix
    # applies (a hostile round: it stayed in place while its velocity pumped the impactor
    # from 50 to 89 m/s, without a message); at rest it is a frozen wall (no warning)
    ("fi_outside_group_velocity_unmoved",
     [R("fix_int", "fix int a esph/integrate"), A("velocity", "velocity b set 0 100 0 units box")],
     "warning:is outside the group of fix esph/integrate int and has a velocity", 2),
    ("fi_outside_group_at_rest", [R("fix_int", "fix int a esph/integrate")], "runs"),
    ("fi_outside_group_velocity_moved",
     [R("fix_int", "fix int a esph/integrate"), A("velocity", "velocity b set -20 0 0 units box"),
      A("velocity", "fix mv b move linear -20 0 0")], "runs"),
    ("pc_rigid_velocity_moved",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"), A("velocity", "velocity b set -20 0 0 units box"),
      A("velocity", "fix mv b move linear -20 0 0")], "runs"),
    # fix move variable with NULL displacement and velocity integrates f / m: infinite for the
    # zero-mass boundary particles in its group (they went NaN and the contact vanished)
    ("pc_rigid_move_variable_null",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"),
      A("velocity", "fix mv b move variable NULL NULL NULL NULL NULL NULL units box")],
     "error:has a non-finite position after step", 2),
    # fix move variable with displacements but no velocities: the body moves, its velocities
    # stay as they were, and the contact and the normals read them (checked every 100 steps)
    ("pc_rigid_move_variable_no_velocity",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"), A("velocity", "variable dxb equal 5*time"),
      A("velocity", "variable zero equal 0.0"),
      A("velocity", "fix mv b move variable v_dxb v_zero v_zero NULL NULL NULL units box"),
      R("run", "run 120")], "warning:without setting the velocities", 2),
    ("pc_rigid_move_variable_velocity",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"), A("velocity", "variable dxb equal 5*time"),
      A("velocity", "variable vxb equal 5"), A("velocity", "variable zero equal 0.0"),
      A("velocity", "fix mv b move variable v_dxb v_zero v_zero v_vxb v_zero v_zero units box"),
      R("run", "run 120")], "runs"),
    ("pc_rigid_move_rotate",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"),
      A("velocity", "fix mv b move rotate 0.0002 0 0 0 0 1 1e-4 units box")], "runs"),
    ("pc_rigid_contact_off", [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
                              R("fix_int", "fix int a esph/integrate"), K("pair", " contact off")],
     "error:need a contact rule"),
    ("pc_rigid_mixed_body", [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
                             R("fix_int", "fix int a esph/integrate"),
                             R("body_b", "set group b i_esph_body 1")],
     "error:rigid and of deformable", 2),
    # fix move on the real particles of a rigid body alone: its boundary particles stayed
    # behind, and a punch so driven pushed with a tenth of its force, without a message
    ("pc_rigid_move_real_only",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"), A("fix_bnd", "variable massive atom mass>0.0"),
      A("fix_bnd", "group real variable massive"), A("fix_bnd", "group rb intersect b real"),
      A("velocity", "fix mv rb move linear -20 0 0")],
     "error:do not move with its real particles", 2),
    # fix recenter on the real particles alone shifts them away from their boundary particles
    # (its shift group is its own); with shift all the whole bodies move
    ("pc_recenter_real_only",
     [A("fix_bnd", "variable massive atom mass>0.0"), A("fix_bnd", "group real variable massive"),
      A("velocity", "fix rc real recenter INIT INIT INIT"), R("run", "run 700")],
     "warning:lie less than 0.15 spacings in front of their body's real", 2),
    ("pc_recenter_shift_all",
     [A("fix_bnd", "variable massive atom mass>0.0"), A("fix_bnd", "group real variable massive"),
      A("velocity", "fix rc real recenter INIT INIT INIT shift all"), R("run", "run 700")],
     "runs"),
    # a face's boundary particles deleted and fix esph/boundary defined again: it reuses the
    # rest, and the surface has a hole there
    ("bf_holes_reused",
     [A("fix_bnd", "region del block -0.00003 0.00003 INF INF INF INF units box"),
      A("fix_bnd", "variable zm atom mass==0.0"), A("fix_bnd", "group zm variable zm"),
      A("fix_bnd", "group delg region del"), A("fix_bnd", "group delg intersect delg zm"),
      A("fix_bnd", "delete_atoms group delg"), A("fix_bnd", "unfix bnd"),
      A("fix_bnd", "fix bnd all esph/boundary spacing 1e-4")],
     "error:so the surface has holes there", 2),
    # a second fix esph/boundary on the real particles alone: the existing boundary particles
    # lie outside its group, and it would make a second surface on top of them
    ("bf_second_on_real_group",
     [A("fix_bnd", "variable massive atom mass>0.0"), A("fix_bnd", "group real variable massive"),
      A("fix_bnd", "unfix bnd"), A("fix_bnd", "fix bnd real esph/boundary spacing 1e-4")],
     "error:would make a second surface on top of the", 2),
    # a run, then the box and the bodies stretched by change_box ... remap: the positions
    # change, the density and stress do not (a rebound 19 % off, silently, before the check)
    ("pc_change_box_remap",
     [B("run", "run 10"), B("run", "change_box all x scale 1.05 remap")],
     "warning:changed shape since the last run without a step", 2),
    # the box alone changed, and the bodies moved rigidly (turned, shifted): the same shape
    ("pc_change_box_rigid_moves",
     [B("run", "run 10"), B("run", "change_box all x final -0.0008 0.0008 units box"),
      B("run", "displace_atoms a rotate -0.0002 0 0 1 1 1 30 units box"),
      B("run", "displace_atoms b move 0.00005 0 0 units box")],
     "runs", 2),
    # fix deform with remap x (its default) moves the particles without their velocities
    ("pc_deform_remap_x",
     [R("boundary", "boundary p f f"), A("velocity", "fix d all deform 1 x erate 1000")],
     "warning:without their velocities: the solid does not feel", 2),
    ("pc_deform_remap_v",
     [R("boundary", "boundary p f f"), A("velocity", "fix d all deform 1 x erate 1000 remap v")],
     "runs"),
    # the same without an atom map (LAMMPS's default for atom_style atomic): the warning
    # names the first particle's body and depth all the same
    ("pc_recenter_real_only_no_map",
     [D("atom_modify"), A("fix_bnd", "variable massive atom mass>0.0"),
      A("fix_bnd", "group real variable massive"),
      A("velocity", "fix rc real recenter INIT INIT INIT"), R("run", "run 700")],
     "warning:(e.g. atom 149 of body 1, 0.1", 2),
    # neigh_modify check no: the lists are rebuilt every N steps whatever the motion; at
    # 50 m/s the blocks close by 1.25 skins in 100 steps, by 0.125 in 10
    ("nb_check_no_fast", [A("neighbor", "neigh_modify every 100 delay 0 check no")],
     "warning:neigh_modify check no rebuilds the neighbour lists every 100 steps", 2),
    ("nb_check_no_slow", [A("neighbor", "neigh_modify every 10 delay 0 check no")], "runs"),
    # an fcc lattice with the mass right for it (a^3 / 4 rho0): the lattice is warned, and
    # not the mass as well (its volume is 0.707 spacing^3 there)
    ("bf_fcc_right_mass",
     [R("lattice", "lattice fcc 1.41421356e-4 origin 0.25 0.25 0.25"),
      R("mass", "set group all mass 5.5506e-9")],
     "onewarning:have no simple cubic neighbourhood", 2),
    # fix aveforce on the real particles of both bodies: they move as one along x
    ("fi_aveforce_two_bodies",
     [A("fix_bnd", "variable massive atom mass>0.0"), A("fix_bnd", "group real variable massive"),
      A("velocity", "fix af real aveforce 0.0 NULL NULL")],
     "warning:averages the forces of real particles of 2 bodies", 2),
    ("fi_aveforce_one_body",
     [A("fix_bnd", "variable massive atom mass>0.0"), A("fix_bnd", "group real variable massive"),
      A("fix_bnd", "group rb intersect b real"), A("velocity", "fix af rb aveforce NULL 0.0 NULL")],
     "runs"),
    # one body ID on two blocks apart: a body in pieces
    ("bf_body_in_pieces",
     [R("rb", "region rb block 0.0001 0.0004 -0.0002 0.0002 -0.0002 0.0002 units box"),
      R("body_b", "set group b i_esph_body 1")],
     "warning:in pieces that no particles within 1.5 spacings", 2),
    # the same blocks with their own body IDs: no warning
    ("bf_bodies_apart", [R("rb", "region rb block 0.0001 0.0004 -0.0002 0.0002 -0.0002 0.0002 units box")],
     "runs"),
    # the same with the whole body: the documented way
    ("pc_rigid_move_whole_body",
     [A("coeff", "pair_coeff 2 2 rho0 7850 shear 80e9 " + MG + " rigid yes"),
      R("fix_int", "fix int a esph/integrate"), A("velocity", "fix mv b move linear -20 0 0")],
     "runs"),
    ("pc_before_pair_style", [M("coeff", "pair")], "error:Pair_coeff command without a pair style"),
    # ---------------- fix esph/integrate ----------------
    ("fi_unknown_keyword", [K("fix_int", " nve")], "error:Unknown fix esph/integrate keyword"),
    # a new integrator in the middle of a contact (as after read_data of a file written in
    # contact): the contact record and the prediction start afresh, said once
    ("fi_new_in_contact",
     [A("run", "unfix int"), A("run", "fix int all esph/integrate"), A("run", "run 5")],
     "warning:engaged in contact", 2),
    ("fi_cfl_missing", [K("fix_int", " cfl")], "error:missing argument"),
    ("fi_cfl_zero", [K("fix_int", " cfl 0")], "error:must be in (0,1]"),
    ("fi_cfl_above_one", [K("fix_int", " cfl 2")], "error:must be in (0,1]"),
    ("fi_cfl_text", [K("fix_int", " cfl fast")], "error:Expected floating point"),
    ("fi_cfl_on", [K("fix_int", " cfl 0.3")], "runs"),
    # above 0.6 the integration gains energy fast (a hostile round: x9 at 0.7, lost atoms at 1.0)
    ("fi_cfl_unsafe", [K("fix_int", " cfl 0.7")], "warning:is above 0.6"),
    ("fi_cfl_half", [K("fix_int", " cfl 0.5")], "runs"),
    # a fixed time step of 1.3 CFL estimates (5e-9 is 0.26 of it)
    ("fi_dt_unsafe", [R("timestep", "timestep 2.5e-8"), R("run", "run 1")],
     "warning:times the CFL estimate"),
    # the boundary particles left out of the integration: the bodies would pass through
    ("fi_group_real_only", [A("fix_bnd", "variable massive atom mass>0.0"),
                            A("fix_bnd", "group real variable massive"),
                            A("fix_bnd", "unfix int"), A("fix_bnd", "fix int real esph/integrate")],
     "error:boundary particles (zero mass"),
    # the vector of fix esph/integrate before the first run and after the pair style changed
    # (a hostile round: segmentation fault, then a read of the deleted pair style)
    ("fi_vector_before_run", [B("run", 'print "V $(f_int[2]) $(f_int[3]) $(f_int[7])"')], "runs"),
    ("fi_vector_pair_replaced", [A("run", "pair_style zero 1.0"), A("run", "pair_coeff * *"),
                                 A("run", 'print "V $(f_int[2]) $(f_int[3]) $(f_int[7])"')],
     "runs"),
    ("fi_dtmax_without_cfl", [K("fix_int", " dtmax 1e-9")], "error:need the cfl keyword"),
    ("fi_dtmax_negative", [K("fix_int", " cfl 0.3 dtmax -1e-9")], "error:dtmax must be > 0"),
    ("fi_dtmin_negative", [K("fix_int", " cfl 0.3 dtmin -1e-9")], "error:dtmin must be > 0"),
    # an EOS that cannot be evaluated in compression (Mie-Grueneisen slope s = 1e300: its
    # sound speed is NaN at the first compression): a run went on with NaN thermo, no
    # message; now the step it happens names the atom and the state (one rank: like LAMMPS's
    # own "Lost atoms", the rank that sees it stops the run, with its own atom)
    ("pc_mg_slope_steep", [R("coeff", "pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen "
                                      "3574 10 1.69")], "warning:diverges at the compression"),
    ("pc_mg_slope_huge", [R("coeff", "pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen "
                                     "3574 1e300 1.69")], "error:has a non-finite state"),
    # compute esph/contact: bodies touching at the start have their row from step 0 (it
    # stopped with "out-of-range" before 2026-12-05); no arguments; a row that never exists
    ("cc_row_at_start", [A("ke", "compute cont all esph/contact"),
                         K("thermo_style", " c_cont[1][3] c_cont[1][5] c_cont[1][12]")], "runs", 2),
    ("cc_scalar_rows", [A("ke", "compute cont all esph/contact"), K("thermo_style", " c_cont")],
     "runs"),
    ("cc_argument", [A("ke", "compute cont all esph/contact 1")], "error:it takes no arguments"),
    ("cc_row_missing", [A("ke", "compute cont all esph/contact"),
                        K("thermo_style", " c_cont[2][3]")], "error:out-of-range"),
    # the base's CFL estimate is about 2.2e-8 s
    ("fi_dtmin_unsafe", [K("fix_int", " cfl 0.3 dtmin 2e-8")], "warning:dtmin 2e-08 is"),
    ("fi_dtmin_safe", [K("fix_int", " cfl 0.3 dtmin 2e-9")], "runs"),
    ("fi_dtmin_above_dtmax", [K("fix_int", " cfl 0.3 dtmin 1e-8 dtmax 1e-9")],
     "error:larger than dtmax"),
    ("fi_move_text", [K("fix_int", " move maybe")], "error:Expected boolean"),
    ("fi_move_no_alone", [K("fix_int", " move no")], "warning:move no"),
    ("fi_scheme_missing", [K("fix_int", " scheme")], "error:scheme"),
    ("fi_scheme_bogus", [K("fix_int", " scheme leapfrog")],
     "error:scheme must be predicted or staggered, got leapfrog"),
    ("fi_scheme_staggered", [K("fix_int", " scheme staggered")], "runs"),
    ("fi_scheme_staggered_np2", [K("fix_int", " scheme staggered")], "runs", 2),
    ("fi_scheme_predicted", [K("fix_int", " scheme predicted")], "same"),
    ("fi_extrapolate_missing", [K("fix_int", " extrapolate")], "error:extrapolate"),
    ("fi_extrapolate_text", [K("fix_int", " extrapolate maybe")], "error:Expected boolean"),
    ("fi_extrapolate_yes", [K("fix_int", " extrapolate yes")], "same"),
    ("fi_extrapolate_no", [K("fix_int", " extrapolate no")], "runs"),
    ("fi_extrapolate_staggered", [K("fix_int", " scheme staggered extrapolate yes")],
     "warning:no effect with scheme staggered"),
    ("fi_extrapolate_paper", [K("fix_int", " extrapolate yes"), K("pair", " contact paper")],
     "warning:is not used with pair esph/solid contact paper"),
    ("fi_scheme_staggered_move_no", [K("fix_int", " move no scheme staggered"),
                                     A("fix_bnd", "fix mv all move linear 0 0 0")],
     "error:scheme staggered needs move yes"),
    ("ps_paper_no_alpha", [K("pair", " contact paper visc 0 1 0.1")], "warning:contact paper with visc alpha 0"),
    ("fi_move_no_with_fix_move",
     [K("fix_int", " move no"), A("fix_bnd", "fix mv all move linear 0 0 0")], "runs"),
    ("fi_twice", [A("fix_int", "fix int2 all esph/integrate")], "error:Only one fix esph/integrate"),
    ("fi_group_unknown", [R("fix_int", "fix int nobody esph/integrate")],
     "error:Could not find fix group ID"),
    ("fi_missing", [D("fix_int"), R("thermo_style", "thermo_style custom step c_ke pe")],
     "error:requires fix esph/integrate"),
    ("fi_with_fix_nve", [A("fix_bnd", "fix nve all nve")], "error:also integrates"),
    ("fi_with_fix_nve_limit", [A("fix_bnd", "fix lim a nve/limit 1e-6")], "error:also integrates"),
    ("fi_with_fix_nve_first", [B("fix_int", "fix nve b nve")], "error:also integrates"),
    # the contact force f_int[8] at the setup of a run after pair_style is redefined: that of
    # the setup force computation (the sum of contact/force over body 1), not the last step's
    ("fi_fc_setup_after_pair_redefined",
     [A("run", PS + "visc 2 2 0.1"), A("run", "pair_coeff * * rho0 7850 shear 40e9 " + MG),
      B("thermo_style", "compute fc a esph/atom contact/force"),
      B("thermo_style", "compute fa a reduce sum c_fc"), K("thermo_style", " c_fa"),
      A("run", "run 0"),
      A("run", "variable stale equal abs(f_int[8]-c_fa)>1e-9*abs(c_fa)"),
      A("run", 'if "${stale} || $(c_fa) <= 0" then "print \'f_int[8] = $(f_int[8]:%.15g) but '
               'the contact force now is $(c_fa:%.15g)\'" "quit 3"'), A("run", "run 5")],
     "runs"),
    # ---------------- fix esph/boundary ----------------
    ("fb_no_spacing", [R("fix_bnd", "fix bnd all esph/boundary")],
     "error:needs the particle spacing"),
    ("fb_spacing_missing", [R("fix_bnd", FB + "spacing")], "error:missing argument"),
    ("fb_spacing_negative", [R("fix_bnd", FB + "spacing -1e-4")], "error:spacing must be > 0"),
    ("fb_spacing_zero", [R("fix_bnd", FB + "spacing 0")], "error:spacing must be > 0"),
    ("fb_spacing_text", [R("fix_bnd", FB + "spacing fine")], "error:Expected floating point"),
    # normals from the regions the blocks were cut from: the blocks' faces (the contact faces'
    # boundary particles lie on the regions' surfaces), rounded edges; no warning
    ("fb_region", [K("fix_bnd", " region ra region rb")], "runs"),
    ("fb_region_np2", [K("fix_bnd", " region ra region rb")], "runs", 2),
    ("fb_region_missing", [K("fix_bnd", " region")], "error:missing argument"),
    # a body cut from a cylinder region: its rims keep their generated normals (the cap's
    # normal replaced the edge's there, and two cylinders side on touched at once)
    ("fb_region_cylinder_edges",
     [R("rb", "region rb cylinder x 0 0 0.00025 0 0.0004 units box"),
      K("fix_bnd", " region ra region rb")], "runs"),
    ("fb_region_unknown", [K("fix_bnd", " region nowhere")], "error:region nowhere does not exist"),
    # a region with open faces has no surface there (LAMMPS still fills its whole shape)
    ("fb_region_open", [R("rb", "region rb cylinder x 0 0 0.00025 0 0.0004 open 1 units box"),
                        K("fix_bnd", " region ra region rb")], "error:has open faces"),
    ("fb_region_dynamic", [A("rb", "variable zero equal 0.0"),
                           A("rb", "region mv block 0 0.0004 -0.0002 0.0002 -0.0002 0.0002 "
                                   "move v_zero NULL NULL units box"),
                           K("fix_bnd", " region mv")],
     "error:must be static"),
    ("fb_region_given", [R("fix_bnd", "fix bnd all esph/boundary given region ra")],
     "error:drop one of the two"),
    # a region that is not the body's: its surface is far from the boundary particles
    ("fb_region_other", [A("rb", "region big block -0.0006 0 -0.0004 0.0004 -0.0004 0.0004 "
                                  "units box"), K("fix_bnd", " region big")],
     "warning:a region must be the one the body was created from"),
    # block B half a spacing inside block A (a hostile round: at rest they stayed inside each
    # other, moving they gained 2.4 % energy, without a message)
    ("fb_bodies_overlap", [A("gb", "displace_atoms b move -0.00005 0 0 units box")],
     "warning:the bodies overlap"),
    # fix aveforce on a group with boundary particles loses their share (momentum +44 %)
    ("fi_aveforce_boundary", [A("velocity", "fix avef all aveforce 0.0 0.0 NULL")],
     "warning:share of its force is lost"),
    # (on the real particles of one body: over both, the bodies would move as one along x,
    # fi_aveforce_two_bodies)
    ("fi_aveforce_real", [A("velocity", "variable massive atom mass>0.0"),
                          A("velocity", "group real variable massive"),
                          A("velocity", "group rb intersect b real"),
                          A("velocity", "fix avef rb aveforce 0.0 0.0 NULL")], "runs"),
    # block B one particle thick: its faces get no boundary particles (a hostile round: a
    # plate flew through a block without a message)
    ("fb_single_layer", [R("rb", "region rb block 0 0.0001 -0.0002 0.0002 -0.0002 0.0002 "
                                 "units box")], "warning:one particle thick"),
    ("fb_spacing_double", [R("fix_bnd", FB + "spacing 2e-4")], "error:set spacing to the"),
    ("fb_spacing_half", [R("fix_bnd", FB + "spacing 5e-5")], "error:set spacing to the"),
    ("fb_spacing_20pct_off", [R("fix_bnd", FB + "spacing 1.2e-4")], "warning:median nearest"),
    # (the boundary particles are placed for it; the particles' volume is 0.86 spacing^3)
    ("fb_spacing_5pct_off", [R("fix_bnd", FB + "spacing 1.05e-4")],
     "warning:reference volume m / rho0 of 0.864 to 0.864 x spacing^3"),
    ("fb_spacing_2pct_off", [R("fix_bnd", FB + "spacing 1.02e-4")], "runs"),
    ("fb_type_invalid", [K("fix_bnd", " type 7")], "error:not a valid atom type"),
    ("fb_type_zero", [K("fix_bnd", " type 0")], "error:not a valid atom type"),
    ("fb_type_text", [K("fix_bnd", " type steel")], "error:type"),
    ("fb_type_2", [K("fix_bnd", " type 2")], "same"),
    ("fb_smooth_below", [K("fix_bnd", " smooth 0.5")], "error:smooth must be in [1,3]"),
    ("fb_smooth_above", [K("fix_bnd", " smooth 4")], "error:smooth must be in [1,3]"),
    ("fb_smooth_text", [K("fix_bnd", " smooth wide")], "error:Expected floating point"),
    ("fb_smooth_2", [K("fix_bnd", " smooth 2")], "runs"),
    ("fb_smooth_1", [K("fix_bnd", " smooth 1")], "same"),
    ("fb_fit_below", [K("fix_bnd", " fit 1")], "error:fit must be 0 (off) or in [2,16]"),
    ("fb_fit_above", [K("fix_bnd", " fit 20")], "error:fit must be 0 (off) or in [2,16]"),
    ("fb_fit_negative", [K("fix_bnd", " fit -3")], "error:fit must be 0 (off) or in [2,16]"),
    ("fb_fit_text", [K("fix_bnd", " fit wide")], "error:Expected floating point"),
    ("fb_fit_missing", [K("fix_bnd", " fit")], "error:fit"),
    ("fb_fit_0", [K("fix_bnd", " fit 0")], "same"),
    ("fb_fit_8", [K("fix_bnd", " fit 8")], "runs"),
    ("fb_unknown_keyword", [K("fix_bnd", " normals out")], "error:Unknown fix esph/boundary keyword"),
    ("fb_turn_missing", [K("fix_bnd", " turn")], "error:missing argument"),
    ("fb_turn_unknown", [K("fix_bnd", " turn rigid")], "error:turn rigid is unknown"),
    ("fb_turn_spin", [K("fix_bnd", " turn spin")], "same"),
    ("fb_turn_body", [K("fix_bnd", " turn body")], "runs"),
    ("fb_turn_body_np2", [K("fix_bnd", " turn body")], "runs", 2),
    # blocks in a box periodic in z, clear of its z ends: rigid spins as without periodicity
    ("fb_turn_body_periodic", [R("boundary", "boundary f f p"), K("fix_bnd", " turn body")],
     "runs"),
    # blocks that fill the z period (infinite in z) have no rigid rotation: interpolated spin
    ("fb_turn_body_spanning", [R("boundary", "boundary f f p"),
                               R("box", "region box block -0.0006 0.0006 -0.0004 0.0004 "
                                 "-0.0002 0.0002"), K("fix_bnd", " turn body")],
     "warning:extend over more than half of a periodic box length"),
    ("fb_turn_body_spanning_np2", [R("boundary", "boundary f f p"),
                                   R("box", "region box block -0.0006 0.0006 -0.0004 0.0004 "
                                     "-0.0002 0.0002"), K("fix_bnd", " turn body")],
     "warning:extend over more than half of a periodic box length", 2),
    ("fb_missing", [D("fix_bnd")], "error:requires fix esph/boundary"),
    ("fb_given_without_particles", [R("fix_bnd", "fix bnd all esph/boundary given")],
     "error:has no boundary particles"),
    ("fb_group_one_body", [R("fix_bnd", "fix bnd a esph/boundary spacing 1e-4")],
     "error:body 2 has real particles but no boundary particles"),
    ("fb_twice", [A("fix_bnd", "fix bnd2 all esph/boundary spacing 1e-4")], "same"),
    ("fb_group_unknown", [R("fix_bnd", "fix bnd nobody esph/boundary spacing 1e-4")],
     "error:Could not find fix group ID"),
    ("fb_box_too_small",
     [R("box", "region box block -0.0004 0.0004 -0.0002 0.0002 -0.0002 0.0002")],
     "error:outside the non-periodic box"),
    # ---------------- command order ----------------
    ("ord_fix_before_pair", [M("fix_int", "pair")], "same"),
    ("ord_fixes_before_pair",
     [M("fix_int", "pair"), M("timestep", "pair"), M("mass", "pair"), M("body_a", "pair"),
      M("body_b", "pair"), M("fix_bnd", "pair")], "same"),
    ("ord_pair_after_run_setup",
     [M("pair", "neighbor"), M("coeff", "neighbor")], "same"),
    ("ord_boundary_before_masses", [M("fix_bnd", "mass")], "error:have zero mass"),
    ("ord_boundary_before_bodies", [M("fix_bnd", "body_a")],
     "error:generated its boundary particles"),
    ("ord_boundary_between_bodies", [M("fix_bnd", "body_b")],
     "error:generated its boundary particles"),
    ("ord_mass_before_any_esph_style", [M("mass", "pair")], "error:Cannot set attribute mass"),
    ("ord_body_before_any_esph_style", [M("body_a", "pair")], "error:i_esph_body"),
    # one body with atom_style sphere (masses exist before any ESPH style): the boundary
    # fix may then be the first ESPH style
    ("ord_boundary_first_sphere",
     [R("atom_style", "atom_style sphere"), D("body_a"), D("body_b"), M("mass", "pair"),
      M("fix_bnd", "pair")], "runs"),
    ("ord_atoms_after_boundary",
     [A("fix_bnd", "create_atoms 1 single 0.0003 0.0003 0.0003 units box"),
      A("fix_bnd", "set atom 241 mass 7.85e-9")],
     "error:generated its boundary particles"),
    ("ord_mass_after_boundary", [A("fix_bnd", "set group b mass 1.57e-8")],
     "error:generated its boundary particles"),
    ("ord_velocity_before_boundary", [M("velocity", "fix_bnd")], "same"),
    ("ord_no_pair_style", [D("pair"), D("coeff")], "error:requires pair style esph/solid"),
    ("ord_other_pair_style", [R("pair", "pair_style zero 2.6e-4"), R("coeff", "pair_coeff * *")],
     "error:requires pair style esph/solid"),
    ("ord_no_bodies_contact", [D("body_a"), D("body_b")], "runs"),
    # after read_restart the pair style and the fixes are defined again, in any order
    ("rs_fixes_without_pair", RESTART + [A("run", "fix int all esph/integrate"),
                                         A("run", FB + "spacing 1e-4"), A("run", "run 5")],
     "error:re-specify non-restarted pair style (esph/solid)"),
    ("rs_fixes_other_pair", RESTART + [A("run", "fix int all esph/integrate"),
                                       A("run", FB + "spacing 1e-4"),
                                       A("run", "pair_style zero 2.6e-4"),
                                       A("run", "pair_coeff * *"), A("run", "run 5")],
     "error:requires pair style esph/solid"),
    ("rs_boundary_without_pair", RESTART + [A("run", FB + "spacing 1e-4"), A("run", "run 5")],
     "error:re-specify non-restarted pair style (esph/solid)"),
    ("rs_fixes_first", RESTART + [A("run", "fix int all esph/integrate"),
                                  A("run", FB + "spacing 1e-4"),
                                  A("run", "pair_style esph/solid 1.3e-4"),
                                  A("run", PC + MG), A("run", "neighbor 2e-5 bin"),
                                  A("run", "run 5")], "runs"),
    # ---------------- hostile per-atom state ----------------
    ("st_density_negative", [A("fix_bnd", "set group a d_esph_rho -7850")],
     "error:d_esph_rho = -7850"),
    ("st_density_inf", [A("fix_bnd", "variable big atom 1e308*10"),
                        A("fix_bnd", "set atom 3 d_esph_rho v_big")], "error:d_esph_rho = inf"),
    ("st_h_negative", [A("fix_bnd", "set group all d_esph_h -1e-4")],
     "error:d_esph_h = -0.0001"),
    ("st_h_huge", [A("fix_bnd", "set group all d_esph_h 1.0")], "error:increase hvar"),
    ("st_energy_inf", [A("fix_bnd", "variable big atom 1e308*10"),
                       A("fix_bnd", "set atom 7 d_esph_e v_big")], "error:d_esph_e = inf"),
    ("st_energy_very_negative", [A("fix_bnd", "set atom 9 d_esph_e -1e9")],
     "error:no sound speed"),
    ("st_density_beyond_eos", [A("fix_bnd", "set atom 9 d_esph_rho 20000")],
     "error:no sound speed"),
    ("st_stress_inf", [A("fix_bnd", "variable big atom 1e308*10"),
                       A("fix_bnd", "set atom 11 d2_esph_s[4] v_big")],
     "error:d2_esph_s[4] = inf"),
    ("st_velocity_create", [R("velocity", "velocity all create 300 4928459")],
     "error:apply it to the real particles"),
    ("st_velocity_inf", [A("fix_bnd", "variable big atom 1e308*10"),
                         R("velocity", "velocity a set v_big 0 0 units box")],
     "error:velocity (inf"),
    ("st_mass_zero_variable",
     [A("fix_bnd", "variable zero atom 0.0"), A("fix_bnd", "set atom 5 mass v_zero")],
     "error:generated its boundary particles"),
    ("st_mass_zero_before_boundary",
     [A("mass", "variable zero atom 0.0"), A("mass", "set atom 5 mass v_zero")],
     "error:atom 5 in group all has zero mass but no normal"),
    ("st_mass_zero_no_boundary_fix",
     [K("pair", " contact off"), D("fix_bnd"), A("mass", "variable zero atom 0.0"),
      A("mass", "set atom 5 mass v_zero")], "error:Atom 5 has zero mass but no boundary normal"),
    ("st_mass_negative",
     [A("mass", "variable neg atom -1.0"), A("mass", "set atom 5 mass v_neg")],
     "error:Invalid mass"),
    ("st_normal_not_unit", [A("fix_bnd", "set group all d2_esph_n[1] 0.5")],
     "error:not a unit normal"),
    ("st_coincident", [A("cb", "create_atoms 1 single " + SITE + " units box")],
     "error:same position"),
    ("st_plastic_strain_negative",
     [K("coeff", " yield 2e8"), A("fix_bnd", "set group a d_esph_epsp -0.1")],
     "error:d_esph_epsp = -0.1"),
    ("st_state_set_by_hand", [B("pair", "fix mine all property/atom d_esph_rho")],
     "error:must not be defined by hand"),
    # ---------------- units, dimension, atom style, boundary ----------------
    # metal and real are converted (tests/physics/test_units.py checks the physics):
    # the SI numbers mean another scene there, which runs; electron is not supported
    ("un_metal", [R("units", "units metal")], "runs"),
    ("un_real", [R("units", "units real")], "runs"),
    ("un_electron", [R("units", "units electron")],
     "error:does not support units electron: expected units si, metal, real"),
    ("un_lj", [R("units", "units lj"), R("lattice", "lattice sc 1e12 origin 0.5 0.5 0.5")],
     "runs"),
    ("un_cgs", [R("units", "units cgs")], "same"),
    ("un_nano", [R("units", "units nano")], "same"),
    ("dim_2d_with_3d_box", [B("boundary", "dimension 2")], "error:2d"),
    ("as_sphere", [R("atom_style", "atom_style sphere")], "same"),
    ("as_charge", [R("atom_style", "atom_style charge")], "same"),
    ("as_ellipsoid", [R("atom_style", "atom_style ellipsoid")], "same"),
    ("am_no_map", [D("atom_modify")], "same"),
    ("newton_off", [B("box", "newton off")], "runs"),
    ("newton_off_after_box", [B("pair", "newton off")], "error:Newton bond change"),
    ("bc_periodic", [R("boundary", "boundary p p p")], "same"),
    # ---------------- run styles and commands that do not fit an SPH solid ----------------
    ("rs_respa", [B("run", "run_style respa 2 2")], "error:does not support run_style respa"),
    ("rs_minimize", [R("run", "minimize 1e-6 1e-6 10 100")], "error:does not support minimize"),
    ("rs_minimize_fire",
     [B("run", "min_style fire"), R("run", "minimize 0 1e-6 10 100")],
     "error:does not support minimize"),
    ("rs_rerun",
     [B("run", "dump d all custom 5 rerun.dump id type x y z vx vy vz"), A("run", "undump d"),
      A("run", "rerun rerun.dump dump x y z vx vy vz")], "warning:a dump holds no SPH state"),
    ("rs_cfl_dt_reset",
     [K("fix_int", " cfl 0.3"), A("fix_int", "fix dtr all dt/reset 1 NULL 1e-8 1e-6")],
     "warning:fix dt/reset wins"),
    ("rs_reset_timestep_in_contact",
     [B("run", "run 10"), B("run", "reset_timestep 0")],
     "warning:contact durations across the reset are wrong"),
    # forward: LAMMPS moves the time on by the steps skipped (found by a hostile round,
    # 2026-12-06: the contact durations took the jump without a word)
    ("rs_reset_timestep_forward_in_contact",
     [B("run", "run 10"), B("run", "reset_timestep 1000")],
     "warning:contact durations across the reset are wrong"),
    # with its time keyword at the time the run ended: nothing moves, nothing to say
    ("rs_reset_timestep_time_kept",
     [B("run", "run 10"), B("run", "reset_timestep 1000 time $(time)")], "runs"),
    # write_data and read_data: the per-type masses ESPH never set are written as 1.0
    # (read_data rejects 0), the user's are kept
    # (the base's blocks are in contact when the file is written: the run from it warns that
    # the contact record and the prediction start afresh)
    ("rs_write_read_data",
     [B("run", "mass 2 3.0"), A("run", "write_data rt.data"), A("run", "clear"),
      A("run", "units si"), A("run", "atom_style atomic"), A("run", "atom_modify map array"),
      A("run", "boundary f f f"), A("run", "pair_style esph/solid 1.3e-4"),
      A("run", "read_data rt.data fix ESPH_STATE NULL ESPH_STATE fix ESPH_STRESS NULL "
               "ESPH_STRESS fix ESPH_NORMAL NULL ESPH_NORMAL"),
      A("run", PC + MG), A("run", "fix int all esph/integrate"), A("run", "timestep 5e-9"),
      A("run", FB + "spacing 1e-4"), A("run", "neighbor 2e-5 bin"),
      A("run", "run 5")], "warning:engaged in contact"),
    ("rs_delete_atoms",
     [A("run", "delete_atoms group a compress no"), A("run", "run 5")],
     "error:define it again (unfix, then fix)"),
    # some boundary particles deleted while their body keeps its real particles: holes in
    # its surface (16 of a rod's end face deleted: the contact came 0.9 us late, no message)
    ("bf_delete_some_boundary",
     [A("run", "variable zb atom (mass==0.0)&&(i_esph_body==1)&&(x>-0.00005)"),
      A("run", "group zb variable zb"), A("run", "delete_atoms group zb compress no"),
      A("run", "run 5")], "error:boundary particles were deleted or lost"),
    ("bf_delete_some_boundary_np2",
     [A("run", "variable zb atom (mass==0.0)&&(i_esph_body==1)&&(x>-0.00005)"),
      A("run", "group zb variable zb"), A("run", "delete_atoms group zb compress no"),
      A("run", "run 5")], "error:boundary particles were deleted or lost", 2),
    # a whole body deleted, its boundary particles with it, the fix defined again: runs
    ("bf_delete_body_refix",
     [A("run", "delete_atoms group b compress no"), A("run", "unfix bnd"),
      A("run", FB + "spacing 1e-4"), A("run", "run 5")], "runs"),
    # pair_style hybrid: the pairs of two esph/solid types given to another sub-style
    # (bodies passed through each other without a message)
    ("ps_hybrid_cross_zero",
     [R("pair", "pair_style hybrid esph/solid 1.3e-4 zero 1.3e-4"),
      R("coeff", "pair_coeff * * esph/solid rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 "
                 "1.69"), A("coeff", "pair_coeff 1 2 zero")],
     "warning:their pairs are given to another sub-style"),
    ("ps_hybrid_overlay_zero",
     [R("pair", "pair_style hybrid/overlay esph/solid 1.3e-4 zero 1.3e-4"),
      R("coeff", "pair_coeff * * esph/solid rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 "
                 "1.69"), A("coeff", "pair_coeff * * zero")], "same"),
    # a fix that moves particles after fix esph/integrate's prediction (post_integrate)
    ("fi_wall_reflect", [A("fix_int", "fix wr all wall/reflect xhi EDGE")],
     "warning:changes positions or velocities of ESPH particles"),
    ("bf_single_particle_body",
     [R("ra", "region ra block -0.0001 0 0 0.0001 0 0.0001 units box")],
     "error:a single particle has no surface"),
    # positions rotated after the boundary particles were made: their normals stay behind
    ("bf_rotate_after_boundary",
     [A("fix_bnd", "displace_atoms b rotate 0.0002 0 0 0 0 1 90 units box")],
     "warning:displace_atoms rotate after fix esph/boundary: rotate before it"),
    ("bf_rotate_before_boundary",
     [B("fix_bnd", "displace_atoms b rotate 0.0002 0 0 0 0 1 90 units box")], "runs"),
    # bodies on another lattice than simple cubic: the boundary particles and the touch's cells
    # are those of a simple cubic lattice (a hostile round: two fcc cubes turned 45 degrees
    # meeting edge to edge passed through each other without a message); fcc and bcc with
    # the spacing their nearest-neighbour distance (0.1 mm), sites clear of the blocks' faces
    ("bf_lattice_fcc", [R("lattice", "lattice fcc 1.4142136e-4 origin 0.25 0.25 0.25")],
     "warning:have no simple cubic neighbourhood"),
    ("bf_lattice_fcc_np2", [R("lattice", "lattice fcc 1.4142136e-4 origin 0.25 0.25 0.25")],
     "warning:have no simple cubic neighbourhood", 2),
    ("bf_lattice_bcc", [R("lattice", "lattice bcc 1.1547005e-4 origin 0.25 0.25 0.25")],
     "warning:have no simple cubic neighbourhood"),
    # a simple cubic lattice turned off the box axes has its cells: no warning
    ("bf_lattice_sc_turned",
     [B("fix_bnd", "displace_atoms all rotate 0 0 0 1 2 3 30 units box"),
      R("box", "region box block -0.0008 0.0008 -0.0008 0.0008 -0.0008 0.0008")], "runs"),
    ("bf_spacing_tenth", [R("fix_bnd", FB + "spacing 1e-5")],
     "error:have no particle of their own body within 3 x spacing"),
    # ---------------- the same errors on two MPI ranks ----------------
    ("mpi_coincident", [A("cb", "create_atoms 1 single " + SITE + " units box")],
     "error:same position", 2),
    ("mpi_density_negative", [A("fix_bnd", "set group b d_esph_rho -7850")],
     "error:d_esph_rho = -7850", 2),
    ("mpi_velocity_create", [R("velocity", "velocity all create 300 4928459")],
     "error:apply it to the real particles", 2),
    ("mpi_boundary_before_bodies", [M("fix_bnd", "body_a")],
     "error:generated its boundary particles", 2),
    ("mpi_group_one_body", [R("fix_bnd", "fix bnd a esph/boundary spacing 1e-4")],
     "error:body 2 has real particles but no boundary particles", 2),
    ("mpi_spacing_double", [R("fix_bnd", FB + "spacing 2e-4")], "error:set spacing to the", 2),
    ("mpi_fix_nve", [A("fix_bnd", "fix nve all nve")], "error:also integrates", 2),
    ("mpi_dimension_1", [K("pair", " dimension 1")], "error:a 1D kernel needs", 2),
    ("mpi_fix_before_pair", [M("fix_int", "pair")], "runs", 2),
    # every optional forward-communicated quantity at once (cone, heat, reconstruction: 32
    # values per atom) in a run that continues another: the communication buffers hold them
    ("mpi_all_forward_split", [K("pair", " contact/normal cone visc/recon vanleer heat 0.1 1.0"),
                               A("run", "run 10")], "runs", 2),
    ("mpi_all_forward_switch_split",
     [K("pair", " contact/normal cone visc/switch 0.1 0.2 visc/recon vanleer heat 0.1 1.0"),
      A("run", "run 10")], "runs", 2),
]


def build(ops):
    """the base input with the operations applied, as text"""
    lines = [list(kv) for kv in BASE]

    def find(key):
        for k, (name, _) in enumerate(lines):
            if name == key:
                return k
        raise KeyError(key)

    for op, key, arg in ops:
        k = find(key)
        if op == "R":
            lines[k][1] = arg
        elif op == "D":
            del lines[k]
        elif op == "A":
            # after the line and after lines inserted after it before (keeps their order)
            k += 1
            while k < len(lines) and lines[k][0].startswith(key + "+"):
                k += 1
            lines.insert(k, [key + "+", arg])
        elif op == "B":
            lines.insert(k, [key + "-", arg])
        elif op == "M":
            line = lines.pop(k)
            lines.insert(find(arg), line)
        elif op == "K":
            lines[k][1] += arg
        else:
            raise ValueError(op)
    return "\n".join(line for _, line in lines) + "\n"
