// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The whole public API of the Heat_diffusion package in one include. Each header of
// CGAL/Heat_diffusion/ can also be included alone, which compiles faster.

#ifndef CGAL_HEAT_DIFFUSION_H
#define CGAL_HEAT_DIFFUSION_H

#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/vertex_normals.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/reconstruction.h>
#include <CGAL/Heat_diffusion/heat_kernel_method.h>
#include <CGAL/Heat_diffusion/operator_normalization.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/denoising_report.h>
#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/point_set_multiscale_features.h>
#include <CGAL/Heat_diffusion/point_set_decomposition.h>
#include <CGAL/Heat_diffusion/point_set_denoising.h>

#endif // CGAL_HEAT_DIFFUSION_H
