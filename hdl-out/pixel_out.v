

module pixel_out(clock,inp$valid,inp$ready,inp$x,inp$y,inp$z,inp$rgb0,inp$rgb1,inp$rgb2,mem$ready,mem$rd_en,mem$rd_addr,mem$rd_z,mem$wr_en,mem$wr_addr,mem$wr_z,mem$wr_rgb,idle);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$x;
    input wire  [9:0] inp$y;
    input wire  [15:0] inp$z;
    input wire  [7:0] inp$rgb0;
    input wire  [7:0] inp$rgb1;
    input wire  [7:0] inp$rgb2;
    input wire  mem$ready;
    output wire  mem$rd_en;
    output wire  [19:0] mem$rd_addr;
    input wire  [15:0] mem$rd_z;
    output wire  mem$wr_en;
    output wire  [19:0] mem$wr_addr;
    output wire  [15:0] mem$wr_z;
    output wire  [23:0] mem$wr_rgb;
    output reg  idle;
    
    // Constant declarations
    localparam  one = 1'b1;
    
    // Stub signals
    reg  chunk$clock;
    reg  chunk$in_valid;
    wire  chunk$in_ready;
    reg  chunk$in_mask;
    reg  [19:0] chunk$in_addr;
    reg  [15:0] chunk$in_z;
    reg  [23:0] chunk$in_rgb;
    wire  chunk$idle;
    reg  [9:0] addr$hi;
    reg  [9:0] addr$lo;
    wire  [19:0] addr$out;
    reg  [7:0] rg$hi;
    reg  [7:0] rg$lo;
    wire  [15:0] rg$out;
    reg  [15:0] rgb$hi;
    reg  [7:0] rgb$lo;
    wire  [23:0] rgb$out;
    
    // Sub module instances
    pixel_out$chunk chunk(
        .clock(chunk$clock),
        .in_valid(chunk$in_valid),
        .in_ready(chunk$in_ready),
        .in_mask(chunk$in_mask),
        .in_addr(chunk$in_addr),
        .in_z(chunk$in_z),
        .in_rgb(chunk$in_rgb),
        .mem$ready(mem$ready),
        .mem$rd_en(mem$rd_en),
        .mem$rd_addr(mem$rd_addr),
        .mem$rd_z(mem$rd_z),
        .mem$wr_en(mem$wr_en),
        .mem$wr_addr(mem$wr_addr),
        .mem$wr_z(mem$wr_z),
        .mem$wr_rgb(mem$wr_rgb),
        .idle(chunk$idle)
    );
    pixel_out$addr addr(
        .hi(addr$hi),
        .lo(addr$lo),
        .out(addr$out)
    );
    pixel_out$rg rg(
        .hi(rg$hi),
        .lo(rg$lo),
        .out(rg$out)
    );
    pixel_out$rgb rgb(
        .hi(rgb$hi),
        .lo(rgb$lo),
        .out(rgb$out)
    );
    
    // Update code
    always @(*) begin
        chunk$clock = clock;
        addr$hi = inp$y;
        addr$lo = inp$x;
        rg$hi = inp$rgb0;
        rg$lo = inp$rgb1;
        rgb$hi = rg$out;
        rgb$lo = inp$rgb2;
        chunk$in_valid = inp$valid;
        chunk$in_mask = one;
        chunk$in_addr = addr$out;
        chunk$in_z = inp$z;
        chunk$in_rgb = rgb$out;
        inp$ready = chunk$in_ready;
        idle = chunk$idle;
    end
    
endmodule // pixel_out


module pixel_out$addr(hi,lo,out);
    
    // Module arguments
    input wire  [9:0] hi;
    input wire  [9:0] lo;
    output reg  [19:0] out;
    
    // Constant declarations
    localparam  shift = 8'ha;
    
    // Update code
    always @(*) begin
        out = (((hi) & 20'hfffff) << shift) | ((lo) & 20'hfffff);
    end
    
endmodule // pixel_out$addr


module pixel_out$chunk(clock,in_valid,in_ready,in_mask,in_addr,in_z,in_rgb,mem$ready,mem$rd_en,mem$rd_addr,mem$rd_z,mem$wr_en,mem$wr_addr,mem$wr_z,mem$wr_rgb,idle);
    
    // Module arguments
    input wire  clock;
    input wire  in_valid;
    output reg  in_ready;
    input wire  in_mask;
    input wire  [19:0] in_addr;
    input wire  [15:0] in_z;
    input wire  [23:0] in_rgb;
    input wire  mem$ready;
    output reg  mem$rd_en;
    output reg  [19:0] mem$rd_addr;
    input wire  [15:0] mem$rd_z;
    output reg  mem$wr_en;
    output reg  [19:0] mem$wr_addr;
    output reg  [15:0] mem$wr_z;
    output reg  [23:0] mem$wr_rgb;
    output reg  idle;
    
    // Stub signals
    wire  depth_test$on;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_mask$d;
    wire  s1_mask$q;
    reg  s1_mask$clock;
    reg  [19:0] s1_addr$d;
    wire  [19:0] s1_addr$q;
    reg  s1_addr$clock;
    reg  [15:0] s1_z$d;
    wire  [15:0] s1_z$q;
    reg  s1_z$clock;
    reg  [23:0] s1_rgb$d;
    wire  [23:0] s1_rgb$q;
    reg  s1_rgb$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_write$d;
    wire  s2_write$q;
    reg  s2_write$clock;
    reg  [19:0] s2_addr$d;
    wire  [19:0] s2_addr$q;
    reg  s2_addr$clock;
    reg  [15:0] s2_z$d;
    wire  [15:0] s2_z$q;
    reg  s2_z$clock;
    reg  [23:0] s2_rgb$d;
    wire  [23:0] s2_rgb$q;
    reg  s2_rgb$clock;
    reg  s3_write$d;
    wire  s3_write$q;
    reg  s3_write$clock;
    reg  [15:0] s3_z$d;
    wire  [15:0] s3_z$q;
    reg  s3_z$clock;
    reg  hit2$d;
    wire  hit2$q;
    reg  hit2$clock;
    reg  hit3$d;
    wire  hit3$q;
    reg  hit3$clock;
    reg  [15:0] lanes$0$rd_z;
    reg  [15:0] lanes$0$s1_z;
    reg  [15:0] lanes$0$s2_z;
    reg  [15:0] lanes$0$s3_z;
    reg  lanes$0$s1_mask;
    reg  lanes$0$s2_write;
    reg  lanes$0$s3_write;
    reg  lanes$0$hit2;
    reg  lanes$0$hit3;
    reg  lanes$0$on;
    wire  lanes$0$pass;
    
    // Local signals
    reg  g_pass$0;
    reg  g_pass$1;
    reg  pass;
    
    // Sub module instances
    pixel_out$chunk$depth_test depth_test(
        .on(depth_test$on)
    );
    pixel_out$chunk$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    pixel_out$chunk$s1_mask s1_mask(
        .d(s1_mask$d),
        .q(s1_mask$q),
        .clock(s1_mask$clock)
    );
    pixel_out$chunk$s1_addr s1_addr(
        .d(s1_addr$d),
        .q(s1_addr$q),
        .clock(s1_addr$clock)
    );
    pixel_out$chunk$s1_z s1_z(
        .d(s1_z$d),
        .q(s1_z$q),
        .clock(s1_z$clock)
    );
    pixel_out$chunk$s1_rgb s1_rgb(
        .d(s1_rgb$d),
        .q(s1_rgb$q),
        .clock(s1_rgb$clock)
    );
    pixel_out$chunk$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    pixel_out$chunk$s2_write s2_write(
        .d(s2_write$d),
        .q(s2_write$q),
        .clock(s2_write$clock)
    );
    pixel_out$chunk$s2_addr s2_addr(
        .d(s2_addr$d),
        .q(s2_addr$q),
        .clock(s2_addr$clock)
    );
    pixel_out$chunk$s2_z s2_z(
        .d(s2_z$d),
        .q(s2_z$q),
        .clock(s2_z$clock)
    );
    pixel_out$chunk$s2_rgb s2_rgb(
        .d(s2_rgb$d),
        .q(s2_rgb$q),
        .clock(s2_rgb$clock)
    );
    pixel_out$chunk$s3_write s3_write(
        .d(s3_write$d),
        .q(s3_write$q),
        .clock(s3_write$clock)
    );
    pixel_out$chunk$s3_z s3_z(
        .d(s3_z$d),
        .q(s3_z$q),
        .clock(s3_z$clock)
    );
    pixel_out$chunk$hit2 hit2(
        .d(hit2$d),
        .q(hit2$q),
        .clock(hit2$clock)
    );
    pixel_out$chunk$hit3 hit3(
        .d(hit3$d),
        .q(hit3$q),
        .clock(hit3$clock)
    );
    pixel_out$chunk$lanes$0 lanes$0(
        .rd_z(lanes$0$rd_z),
        .s1_z(lanes$0$s1_z),
        .s2_z(lanes$0$s2_z),
        .s3_z(lanes$0$s3_z),
        .s1_mask(lanes$0$s1_mask),
        .s2_write(lanes$0$s2_write),
        .s3_write(lanes$0$s3_write),
        .hit2(lanes$0$hit2),
        .hit3(lanes$0$hit3),
        .on(lanes$0$on),
        .pass(lanes$0$pass)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_mask$clock = clock;
        s1_addr$clock = clock;
        s1_z$clock = clock;
        s1_rgb$clock = clock;
        s2_valid$clock = clock;
        s2_write$clock = clock;
        s2_addr$clock = clock;
        s2_z$clock = clock;
        s2_rgb$clock = clock;
        s3_write$clock = clock;
        s3_z$clock = clock;
        hit2$clock = clock;
        hit3$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_mask$d = s1_mask$q;
        s1_addr$d = s1_addr$q;
        s1_z$d = s1_z$q;
        s1_rgb$d = s1_rgb$q;
        s2_valid$d = s2_valid$q;
        s2_write$d = s2_write$q;
        s2_addr$d = s2_addr$q;
        s2_z$d = s2_z$q;
        s2_rgb$d = s2_rgb$q;
        s3_write$d = s3_write$q;
        s3_z$d = s3_z$q;
        hit2$d = hit2$q;
        hit3$d = hit3$q;
        in_ready = mem$ready;
        mem$rd_en = 32'h0;
        if (in_valid & depth_test$on) begin
            mem$rd_en = in_mask;
        end
        mem$rd_addr = in_addr;
        g_pass$0 = 32'h0;
        lanes$0$rd_z = mem$rd_z;
        lanes$0$s1_z = s1_z$q;
        lanes$0$s2_z = s2_z$q;
        lanes$0$s3_z = s3_z$q;
        lanes$0$s1_mask = s1_mask$q;
        lanes$0$s2_write = s2_write$q;
        lanes$0$s3_write = s3_write$q;
        lanes$0$hit2 = hit2$q;
        lanes$0$hit3 = hit3$q;
        lanes$0$on = depth_test$on;
        g_pass$1 = g_pass$0 | lanes$0$pass;
        pass = g_pass$1;
        mem$wr_en = s2_write$q;
        mem$wr_addr = s2_addr$q;
        mem$wr_z = s2_z$q;
        mem$wr_rgb = s2_rgb$q;
        idle = ~s1_valid$q & ~s2_valid$q;
        if (mem$ready) begin
            s1_valid$d = in_valid;
            s1_mask$d = 32'h0;
            if (in_valid) begin
                s1_mask$d = in_mask;
            end
            s1_addr$d = in_addr;
            s1_z$d = in_z;
            s1_rgb$d = in_rgb;
            hit2$d = s1_addr$q == in_addr;
            hit3$d = s2_addr$q == in_addr;
            s2_valid$d = s1_valid$q;
            s2_write$d = pass;
            s2_addr$d = s1_addr$q;
            s2_z$d = s1_z$q;
            s2_rgb$d = s1_rgb$q;
            s3_write$d = s2_write$q;
            s3_z$d = s2_z$q;
        end
    end
    
endmodule // pixel_out$chunk


module pixel_out$chunk$depth_test(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // pixel_out$chunk$depth_test


module pixel_out$chunk$hit2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$hit2


module pixel_out$chunk$hit3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$hit3


module pixel_out$chunk$lanes$0(rd_z,s1_z,s2_z,s3_z,s1_mask,s2_write,s3_write,hit2,hit3,on,pass);
    
    // Module arguments
    input wire  [15:0] rd_z;
    input wire  [15:0] s1_z;
    input wire  [15:0] s2_z;
    input wire  [15:0] s3_z;
    input wire  s1_mask;
    input wire  s2_write;
    input wire  s3_write;
    input wire  hit2;
    input wire  hit3;
    input wire  on;
    output reg  pass;
    
    // Constant declarations
    localparam  at = 16'h0;
    localparam  lane_bit = 1'b1;
    
    // Local signals
    reg  [15:0] z;
    reg  [15:0] old_z;
    
    // Update code
    always @(*) begin
        old_z = ((rd_z >> at) & 16'hffff);
        if (((s3_write & lane_bit) != 32'h0) & hit3) begin
            old_z = ((s3_z >> at) & 16'hffff);
        end
        if (((s2_write & lane_bit) != 32'h0) & hit2) begin
            old_z = ((s2_z >> at) & 16'hffff);
        end
        z = ((s1_z >> at) & 16'hffff);
        pass = s1_mask & lane_bit;
        if (on & (z >= old_z)) begin
            pass = 32'h0;
        end
    end
    
endmodule // pixel_out$chunk$lanes$0


module pixel_out$chunk$s1_addr(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s1_addr


module pixel_out$chunk$s1_mask(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s1_mask


module pixel_out$chunk$s1_rgb(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s1_rgb


module pixel_out$chunk$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s1_valid


module pixel_out$chunk$s1_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s1_z


module pixel_out$chunk$s2_addr(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s2_addr


module pixel_out$chunk$s2_rgb(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s2_rgb


module pixel_out$chunk$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s2_valid


module pixel_out$chunk$s2_write(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s2_write


module pixel_out$chunk$s2_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s2_z


module pixel_out$chunk$s3_write(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s3_write


module pixel_out$chunk$s3_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$chunk$s3_z


module pixel_out$rg(hi,lo,out);
    
    // Module arguments
    input wire  [7:0] hi;
    input wire  [7:0] lo;
    output reg  [15:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 16'hffff) << shift) | ((lo) & 16'hffff);
    end
    
endmodule // pixel_out$rg


module pixel_out$rgb(hi,lo,out);
    
    // Module arguments
    input wire  [15:0] hi;
    input wire  [7:0] lo;
    output reg  [23:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 24'hffffff) << shift) | ((lo) & 24'hffffff);
    end
    
endmodule // pixel_out$rgb
